#!/usr/bin/env python3
"""Checks of the grain-boundary runs (tests/grains.cmake; doc/validation.md,
"Grain boundaries and densification"). Prints what it measured; exit code 1
if a check fails.

  check_grains.py law RUN C_GB ENERGY_RATIO BODY_DIM TOLERANCE
      every contact's approach rate in RUN/grain_boundaries.csv against the
      two-grain law u = C_gb (P sin(psi/2) - A kappa_root) / G of the radius
      and root curvature it was computed from (BODY_DIM 2: A = 2a, P = 2,
      G = 2a^3/3; 3: A = pi a^2, P = 2 pi a, G = pi a^4/8); with the
      implicit law's damping g_e (contact_damping) u (1 + g_e) is.
  check_grains.py densify RUN MIN_APPROACH MAX_VOLUME_CHANGE MAX_GRAIN_CHANGE
      the grains approach by at least MIN_APPROACH (relative, last row of
      grain_centre_distance_change_mean), |volume_change| and
      grain_volume_change_max stay below their limits at every row.
  check_grains.py centroids RUN REFERENCE RELATIVE_TOLERANCE VOLUME_LIMIT
      the approach of the power-cell centroids of the solid (the packing
      analysis' centre_distance_change, measured on the level set) beyond
      that of REFERENCE (the same scene without grain boundaries: surface
      diffusion moves the centroids too) against the rigid grains'
      (grain_centre_distance_change_mean) at the last row; and the solid
      volume the grain boundaries lose, |volume_change - that of
      REFERENCE|, below VOLUME_LIMIT.
  check_grains.py equal RUN RELATIVE_TOLERANCE
      at the last step of grain_boundaries.csv every pair's
      centre_distance_change and radius agree within the tolerance of
      their mean.
  check_grains.py kinetics RUN R C_GB T_FIT --csv OUT.csv
      two equal spheres (3D contact law): the grain-boundary radius a
      against the initial-stage law derived for the model in
      doc/numerics.md, (a/R)^6 = 192 C_gb t / R^4 (exponents n = 6, m = 4
      of the paper's Table 2), and the approach h (half the centre
      distance's decrease) against Coble's neck geometry h = a^2 / (4 R);
      the exponent 1/n of a fitted over t >= T_FIT; writes OUT.csv.
  check_grains.py same RUN_A RUN_B COLUMN RELATIVE_TOLERANCE
      COLUMN of RUN_A/metrics.csv and RUN_B/metrics.csv agree at the rows of
      equal time, relative to the largest |value| of RUN_A.
  check_grains.py equilibrium RUN RATIO BODY_DIM [--share S] [--row N] [--csv OUT.csv]
      two equal grains at their end state against the exact equilibrium
      of the same solid volume (doc/numerics.md, "The dihedral angle at the
      triple line"): two truncated discs (BODY_DIM 2) or spheres (3)
      meeting at psi, cos(psi/2) = RATIO / 2; prints the radius (the
      circle fitted to each grain), the grain-boundary radius (where the
      near circles meet its plane; the rays' in runs without that column),
      the fitted circles' centre distance and the dihedral angle, measured
      and exact;
      with --csv the table over the run; --share S: the domain holds the
      share S of the pair (a quarter box: 0.25), its solid volume is S
      times the pair's; --row N: the run is a closed row of N equal grains
      (2D, every grain cut by its two grain boundaries; grains_ring_2d.prm),
      every grain boundary against the exact state of the row.
  check_grains.py spacing RUN RATIO N D0 COLUMN LOW HIGH [--csv OUT.csv]
      a closed row of N equal grains (grains_ring_2d.prm) with the centre
      spacing D0 at t = 0: the spacing D0 (1 + COLUMN) of RUN/metrics.csv
      at the last row against the exact equilibrium's (`equilibrium
      --row N`), d / d_exact - 1 within [LOW, HIGH]. COLUMN:
      grain_centre_distance_change_mean (the rigid grains, against the
      exact centres' spacing) or centre_distance_change_mean (the packing
      analysis' power-cell centroids, also without grain boundaries,
      against the exact grains' centroids' spacing, 6.1 % above their
      centres' at psi = 120 degrees and N = 12; at t = 0 the centroids'
      spacing is within 3e-4 of D0); --csv: the spacing over the run.
  check_grains.py conserved RUN TOLERANCE
      every grain keeps its share of the solid: at every row of
      metrics.csv grain_volume_change_max exceeds |volume_change| (each
      grain's volume may follow the solid's) by at most TOLERANCE.
  check_grains.py settled RUN RATIO BODY_DIM T_FROM TOLERANCE TOLERANCE_DEGREES [SHARE] [--row N]
      the pair of `equilibrium` at every row with time >= T_FROM: R, a
      and d within the relative TOLERANCE of the exact end state, psi's
      mean over those rows within TOLERANCE_DEGREES; prints the largest
      errors, psi's range and the rigid grains' drift. SHARE, --row: as
      `equilibrium`'s --share, --row.
  check_grains.py settling OUT.csv T_FROM LABEL RUN RATIO BODY_DIM EVERY ...
                           [--share S]
      per run (every EVERY-th row at time >= T_FROM): the largest errors
      of `settled`, psi's range and mean, the rigid grains' mean approach
      rate and their centre distance's change, the solid's volume_change
      at the last row; writes OUT.csv. --share: as `equilibrium`'s, for
      every run.
  check_grains.py bias OUT.csv T_FROM T_TO LABEL RUN ...
      per run, the means over the rows with T_FROM <= time <= T_TO of
      what the contact law reads: the volume correction's speed, the
      neck-root curvature kappa' and the explicit one against the fitted
      circles' 1/R; the rigid approach rate's mean and the centre
      distance's change; writes OUT.csv.
  check_grains.py swing RUN RATIO BODY_DIM T_FROM [--share S]
      the pair of `equilibrium` over the rows with time >= T_FROM: the
      range and mean of R's, a's (near circles and rays) and d's errors
      and their mean change between consecutive rows (the swing of single
      rows), psi's and the rigid approach rate's range and mean. --share:
      as `equilibrium`'s.
  check_grains.py resting RUN T_FROM [LIMIT]
      the first contact's rigid approach rate over the steps with time >=
      T_FROM: its range and mean change between steps (the explicit
      contact law's period-2 oscillation swings it by +-10 at R/h = 16,
      doc/numerics.md "Settling: the contact law's step"); LIMIT: fail if
      |u| exceeds it.
  check_grains.py centroids-row RUN RATIO N [--from T --limit L] [--csv OUT.csv]
      a closed row of N grains: per row, the rigid centres' spacing
      against the exact state's d, the grains' centroids' spacing
      (centroid_distance) against the exact grains' centroids', and the
      centroids' offset from the rigid centres; --limit: the centroids'
      spacing within the relative L at every row with time >= T.
  check_grains.py angle RUN RATIO T_FROM TOLERANCE_DEGREES
      the dihedral angle of grain_boundaries.csv at every row with time
      >= T_FROM (the triple line relaxed) within TOLERANCE_DEGREES of psi,
      cos(psi/2) = RATIO / 2; prints the range measured.
  check_grains.py initial RUN R TOLERANCE_DEGREES RELATIVE_TOLERANCE
      step 0 of grain_boundaries.csv (overlapping circles of radius R),
      every grain boundary: the dihedral angle where the circles meet,
      cos(psi/2) = d / (2 R), within TOLERANCE_DEGREES, the fitted radius
      and centre distance within RELATIVE_TOLERANCE of R and d.
  check_grains.py disc RUN T_FROM RELATIVE_TOLERANCE
      a 2D pair at gamma_gb = 0 (psi = 180 degrees): its end state is one
      disc of the solid's area A; at every row of metrics.csv with time >=
      T_FROM the interface length within RELATIVE_TOLERANCE of 2 sqrt(pi
      A); prints the range and the rigid centres' distance over those rows.
  check_grains.py bracket RUN FAST FACTOR T_TO
      a pair of two materials (RUN) between the pairs of one material
      each: FAST, a run with the faster grain's coefficients on both
      grains, and the same with both coefficients times FACTOR (< 1),
      which is FAST at FACTOR t (the flow is linear in the coefficients).
      At every row of RUN with 0 < time <= T_TO the centres' approach
      (centre_distance_change) lies between FAST's at FACTOR t and at t
      (read by linear interpolation); prints how far inside.
"""
import csv
import math
import os
import sys


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def law(run, c_gb, ratio, body, tolerance):
    sin_half = math.sqrt(1 - (ratio / 2) ** 2)
    worst, count, damping = 0.0, 0, 0.0
    for row in rows(run + "/grain_boundaries.csv"):
        u, a, kappa = row["approach_rate"], row["rate_radius"], row["root_curvature"]
        if math.isnan(u):
            continue
        if body == 2:
            area, perimeter, g = 2 * a, 2.0, 2 * a ** 3 / 3
        else:
            area, perimeter, g = math.pi * a * a, 2 * math.pi * a, math.pi * a ** 4 / 8
        # The implicit law's damping (1 + g) G u = C_gb F; 0 for the
        # explicit law (and in tables written before the column).
        expected = c_gb * (perimeter * sin_half - area * kappa) / g / (
            1 + row.get("contact_damping", 0.0))
        worst = max(worst, abs(u - expected) / abs(expected))
        damping = max(damping, row.get("contact_damping", 0.0))
        count += 1
    print(f"law: {count} contacts, largest relative deviation {worst:.3g}, "
          f"largest damping {damping:.3g}")
    if count == 0 or worst > tolerance:
        fail(f"approach rate off the law by {worst:.3g} > {tolerance}")


def densify(run, min_approach, max_volume, max_grain):
    metrics = rows(run + "/metrics.csv")
    approach = -metrics[-1]["grain_centre_distance_change_mean"]
    volume = max(abs(r["volume_change"]) for r in metrics)
    grain = max(r["grain_volume_change_max"] for r in metrics)
    print(f"densify: approach {approach:.4g} at t = {metrics[-1]['time']:.4g}, "
          f"max |volume_change| {volume:.3g}, max grain_volume_change "
          f"{grain:.3g}")
    if not approach >= min_approach:
        fail(f"approach {approach:.4g} < {min_approach}")
    if volume > max_volume or grain > max_grain:
        fail("solid or grain volume not conserved")


def conserved(run, tolerance):
    metrics = rows(run + "/metrics.csv")
    excess = max(r["grain_volume_change_max"] - abs(r["volume_change"])
                 for r in metrics)
    print(f"conserved: largest grain_volume_change_max - |volume_change| "
          f"{excess:.3g} over {len(metrics)} rows")
    if excess > tolerance:
        fail(f"a grain's volume moved by {excess:.3g} beyond the solid's "
             f"(limit {tolerance})")


def centroids(run, reference, tolerance, volume_limit):
    last = rows(run + "/metrics.csv")[-1]
    last_reference = rows(reference + "/metrics.csv")[-1]
    rigid = last["grain_centre_distance_change_mean"]
    measured = last["centre_distance_change"] - \
        last_reference["centre_distance_change"]
    lost = abs(last["volume_change"] - last_reference["volume_change"])
    print(f"centroids: volume lost to the grain boundaries {lost:.3g}")
    if lost > volume_limit:
        fail(f"volume lost {lost:.3g} > {volume_limit}")
    deviation = abs(measured - rigid) / abs(rigid)
    print(f"centroids: rigid {rigid:.5g}, centroids {measured:.5g}, "
          f"relative deviation {deviation:.3g}")
    if deviation > tolerance:
        fail(f"deviation {deviation:.3g} > {tolerance}")


def equal(run, tolerance):
    table = rows(run + "/grain_boundaries.csv")
    last = [r for r in table if r["step"] == table[-1]["step"]]
    for column in ("centre_distance_change", "radius"):
        values = [r[column] for r in last]
        mean = sum(values) / len(values)
        spread = max(abs(v - mean) for v in values) / abs(mean)
        print(f"equal: {len(values)} pairs at step {int(last[0]['step'])}, "
              f"{column} mean {mean:.5g}, spread {spread:.3g}")
        if spread > tolerance:
            fail(f"{column} spread {spread:.3g} > {tolerance}")


def bracket(run, fast, factor, t_to):
    def history(path):
        table = [(r["time"], -r["centre_distance_change"])
                 for r in rows(path + "/grain_boundaries.csv")]
        return sorted(table)

    def at(table, t):
        for (t0, v0), (t1, v1) in zip(table, table[1:]):
            if t0 <= t <= t1:
                return v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        fail(f"time {t:g} outside the reference run")

    reference = history(fast)
    worst, count = math.inf, 0
    for t, approach in history(run):
        if not 0 < t <= t_to:
            continue
        low, high = at(reference, factor * t), at(reference, t)
        # Where in [low, high] the pair lies: 0 at the slow bound, 1 at the
        # fast one.
        share = (approach - low) / (high - low) if high > low else math.nan
        worst = min(worst, share, 1 - share)
        count += 1
    print(f"bracket: {count} rows to t = {t_to:g}; the approach lies "
          f"inside the one-material bounds by at least {worst:.3g} of "
          f"their gap")
    if count == 0 or not worst > 0:
        fail("the two-material pair's approach leaves its bounds")


def same(run_a, run_b, column, tolerance):
    a = {r["time"]: r[column] for r in rows(run_a + "/metrics.csv")}
    b = {r["time"]: r[column] for r in rows(run_b + "/metrics.csv")}
    times = sorted(set(a) & set(b))
    scale = max(abs(v) for v in a.values())
    worst = max(abs(a[t] - b[t]) for t in times) / scale
    print(f"same: {column} at {len(times)} common times, final "
          f"{a[times[-1]]:.5g} vs {b[times[-1]]:.5g}, largest difference "
          f"{worst:.3g} of {scale:.4g}")
    if len(times) < 2 or worst > tolerance:
        fail(f"{column} differs by {worst:.3g} > {tolerance}")


def kinetics(run, radius, c_gb, t_fit, out):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import validation_data
    metrics = [r for r in rows(run + "/metrics.csv") if r["time"] > 0]
    table = []
    for r in metrics:
        a = r["grain_boundary_radius_mean"]
        h = -r["grain_centre_distance_change_mean"] * run_distance(run) / 2
        law = (192 * c_gb * r["time"] / radius ** 4) ** (1 / 6)
        table.append((r["time"], a / radius, law, (a / radius / law) ** 6,
                      h / radius, a * a / (4 * radius * radius)))
    fit = [(math.log(t), math.log(a)) for t, a, *_ in table if t >= t_fit]
    n = len(fit)
    mx = sum(x for x, _ in fit) / n
    my = sum(y for _, y in fit) / n
    slope = sum((x - mx) * (y - my) for x, y in fit) / \
        sum((x - mx) ** 2 for x, _ in fit)
    ratios = [row[3] for row in table if row[0] >= t_fit]
    print(f"kinetics: a ~ t^{slope:.4f} (n = {1 / slope:.2f}) over "
          f"t >= {t_fit} ({n} rows); (a/R)^6 / (192 C t / R^4) from "
          f"{min(ratios):.3f} to {max(ratios):.3f}; last row a/R "
          f"{table[-1][1]:.4f} against the law's {table[-1][2]:.4f}, "
          f"h/R {table[-1][4]:.5f} against a^2/(4R^2) {table[-1][5]:.5f}")
    validation_data.refuse_shorter(out, table)
    with open(out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time", "a_over_R", "law_a_over_R", "ratio_sixth_power",
                         "approach_over_R", "coble_approach_over_R"])
        writer.writerows([[f"{v:.6g}" for v in row] for row in table])


def exact_equilibrium(volume, ratio, body, grains=0):
    """(R, a, d, psi in degrees) of two equal grains of total volume
    `volume` (area in 2D) meeting at psi, cos(psi/2) = ratio / 2; grains > 0:
    of a closed row of `grains` equal grains (2D) of total area `volume`."""
    c = ratio / 2
    beta = math.acos(c)
    if grains > 0:
        # Each grain: a disc of radius R less the two segments beyond its
        # grain boundaries at R cos(beta) from its centre (doc/numerics.md,
        # "The periodic row of grains"): area R^2 (pi - psi + sin(psi)).
        if body != 2:
            fail("a closed row is a 2D scene")
        radius = math.sqrt(volume / grains / (math.pi - 2 * beta + 2 * math.sin(beta) * c))
    elif body == 2:
        # Each grain: a disc of radius R less the segment beyond the chord
        # at R cos(beta): area R^2 (pi - beta + sin(beta) cos(beta)).
        radius = math.sqrt(volume / 2 / (math.pi - beta + math.sin(beta) * c))
    else:
        # A ball less the cap of height R (1 - c): pi R^3 (4 - (1 - c)^2
        # (2 + c)) / 3.
        radius = (volume / 2 / (math.pi * (4 - (1 - c) ** 2 * (2 + c)) / 3)) ** (1 / 3)
    return radius, radius * math.sin(beta), 2 * radius * c, 2 * math.degrees(beta)


def row_centroid_spacing(volume, ratio, grains):
    """The spacing of the grains' centroids in the exact state of a closed
    row of `grains` equal grains of total area `volume` (2D). Each grain is
    a disc of radius R about its centre at rho from the ring's centre O,
    less two segments of area s = R^2 (beta - sin(beta) cos(beta)) whose
    centroids lie g = 2 R^3 sin(beta)^3 / (3 s) from the disc's centre
    along the normals of the cuts, the rays from O at +-pi/N: the cuts are
    turned towards O, so the grain's centroid lies 2 s g sin(pi/N) / A
    further out than its centre, and the centroids' spacing exceeds d (by
    6.1 % at psi = 120 degrees, N = 12)."""
    radius, _, d, _ = exact_equilibrium(volume, ratio, 2, grains)
    beta = math.acos(ratio / 2)
    area = volume / grains
    rho = d / 2 / math.sin(math.pi / grains)
    shift = 4 * radius ** 3 * math.sin(beta) ** 3 / 3 * \
        math.sin(math.pi / grains) / area
    return 2 * (rho + shift) * math.sin(math.pi / grains)


def equilibrium_table(run, ratio, body, share=1, grains=0):
    """Per row of RUN/grain_boundaries.csv with a metrics row: step, time,
    measured R, a, d, psi and their exact values at the row's volume (the
    domain holding the share `share` of the pair, or a closed row of `grains`
    grains)."""
    metrics = rows(run + "/metrics.csv")
    pairs = rows(run + "/grain_boundaries.csv")
    volume = {row["step"]: row["solid_volume"] / share for row in metrics}
    table = []
    for row in pairs:
        if row["step"] not in volume:
            continue
        exact = exact_equilibrium(volume[row["step"]], ratio, body, grains)
        measured = (row["fitted_radius"], gb_radius(row),
                    row["fitted_centre_distance"], row["dihedral_angle"])
        table.append((row["step"], row["time"]) + measured + exact +
                     (row["radius"],))
    return table


def gb_radius(row):
    """The grain boundary's radius a of a row of grain_boundaries.csv as
    the exact state defines it: where the near circles (those of the
    dihedral angle) meet the boundary's plane, the sharp triple line. The
    rays (`radius`, the contact law's a) read the discrete groove, which
    the kink's ridge rounds over k cells: 1.2-1.5 % wider at R/h = 16-32
    (doc/validation.md, "Settling the pair: the contact law's step"). Runs
    without that column, or rows without a near circle: the rays'."""
    a = row.get("fitted_gb_radius", math.nan)
    return a if math.isfinite(a) else row["radius"]


def equilibrium(run, ratio, body, out, share=1, grains=0):
    table = equilibrium_table(run, ratio, body, share, grains)
    last = table[-1]
    names = ("radius R", "grain-boundary radius a", "centre distance d",
             "dihedral angle psi (degrees)")
    print("t = %g (step %d), gamma_gb / gamma_s = %g" % (last[1], last[0], ratio))
    for k, name in enumerate(names):
        m, e = last[2 + k], last[6 + k]
        error = m - e if k == 3 else (m - e) / e
        print("  %-30s measured %.5g exact %.5g  %s %.3g" %
              (name, m, e, "difference" if k == 3 else "relative error", error))
    if out:
        with open(out, "w") as f:
            f.write("step,time,radius,gb_radius,centre_distance,dihedral_angle,"
                    "exact_radius,exact_gb_radius,exact_centre_distance,"
                    "exact_dihedral_angle,gb_radius_rays\n")
            for r in table:
                f.write(",".join("%.8g" % v for v in r) + "\n")


def settling(run, ratio, body, t_from, every=1, share=1, grains=0):
    """Over the rows with time >= t_from (every `every`-th row): their
    number, the largest relative errors of R, a, d, psi's least, largest
    and mean, its exact value, the rigid grains' approach rate (mean) and
    their centre distance's relative change over those rows (the domain
    holding the share `share` of the pair, or a closed row of `grains`
    grains)."""
    table = [r for r in equilibrium_table(run, ratio, body, share, grains)
             if r[1] >= t_from]
    if not table:
        fail("no row at t >= %g" % t_from)
    table = table[::every]
    largest = [max(abs(r[2 + k] - r[6 + k]) / r[6 + k] for r in table)
               for k in range(3)]
    psi = [r[5] for r in table]
    pairs = [row for row in rows(run + "/grain_boundaries.csv")
             if row["time"] >= t_from]
    rates = [row["approach_rate"] for row in pairs
             if not math.isnan(row["approach_rate"])]
    rate = sum(rates) / len(rates)
    drift = pairs[-1]["centre_distance"] / pairs[0]["centre_distance"] - 1
    volume_change = rows(run + "/metrics.csv")[-1]["volume_change"]
    return (len(table), *largest, min(psi), max(psi), sum(psi) / len(psi),
            table[0][9], rate, drift, volume_change)


def settling_table(out, t_from, cases, share=1):
    """cases: LABEL RUN RATIO BODY_DIM EVERY, five words each."""
    with open(out, "w") as f:
        f.write("case,run,t_from,rows,R_error_max,a_error_max,d_error_max,"
                "psi_min,psi_max,psi_mean,psi_exact,approach_rate_mean,"
                "rigid_distance_change,volume_change_end\n")
        for k in range(0, len(cases), 5):
            label, run, ratio, body, every = cases[k:k + 5]
            values = settling(run, float(ratio), int(body), t_from, int(every),
                              share)
            f.write("%s,%s,%g," % (label, os.path.basename(run), t_from) +
                    ",".join("%.5g" % v for v in values) + "\n")
            print(label, " ".join("%.4g" % v for v in values))


def bias(out, t_from, t_to, cases):
    """The contact law's inputs over t_from <= t <= t_to, per case (LABEL
    RUN, two words each): the volume correction's speed, the neck-root
    curvature the law reads (kappa'), the explicit one, the fitted
    circles' 1/R (all means over the rows), the rigid approach rate's mean
    and the rigid centre distance's relative change."""
    with open(out, "w") as f:
        f.write("case,run,t_from,t_to,rows,steps,volume_correction_speed_mean,"
                "root_curvature_mean,root_curvature_explicit_mean,"
                "inverse_fitted_radius_mean,root_bias,approach_rate_mean,"
                "rigid_distance_change\n")
        for k in range(0, len(cases), 2):
            label, run = cases[k:k + 2]
            speed = {row["step"]: row["volume_correction_speed"]
                     for row in rows(run + "/metrics.csv")}
            pairs = [row for row in rows(run + "/grain_boundaries.csv")
                     if t_from <= row["time"] <= t_to and row["step"] in speed]
            if not pairs:
                fail("%s: no row in [%g, %g]" % (run, t_from, t_to))

            def mean(values):
                return sum(values) / len(values)
            root = mean([r["root_curvature"] for r in pairs])
            inverse = mean([1 / r["fitted_radius"] for r in pairs])
            values = (len(pairs), pairs[-1]["step"],
                      mean([speed[r["step"]] for r in pairs]), root,
                      mean([r["root_curvature_explicit"] for r in pairs]),
                      inverse, root / inverse - 1,
                      mean([r["approach_rate"] for r in pairs]),
                      pairs[-1]["centre_distance"] /
                      pairs[0]["centre_distance"] - 1)
            f.write("%s,%s,%g,%g," % (label, os.path.basename(run), t_from,
                                      t_to) +
                    ",".join("%.5g" % v for v in values) + "\n")
            print(label, " ".join("%.4g" % v for v in values))


def settled(run, ratio, body, t_from, tolerance, tolerance_degrees, share=1,
            grains=0):
    n, *largest, low, high, mean, exact, rate, drift, _ = settling(
        run, ratio, body, t_from, share=share, grains=grains)
    # psi's mean: a single row's reading (circles fitted near the line)
    # scatters by 10-40 degrees on these meshes (doc/validation.md).
    off = abs(mean - exact)
    print("settled over %d rows at t >= %g: largest relative errors R %.3g, "
          "a %.3g, d %.3g; psi %.4g to %.4g (exact %.4g); rigid approach "
          "rate %.3g (mean), centre distance %+.3g" %
          (n, t_from, *largest, low, high, exact, rate, drift))
    print("  psi's mean %.4g" % mean)
    if not max(largest) <= tolerance:
        fail("R, a or d off by more than %g" % tolerance)
    if not off <= tolerance_degrees:
        fail("dihedral angle's mean off by more than %g degrees" %
             tolerance_degrees)


def swing(run, ratio, body, t_from, share=1):
    """The pair's rows with time >= t_from against the exact state: per
    quantity (R, a where the near circles meet the plane, a of the rays,
    d) the range and mean of the relative error (per cent) and the mean
    change between consecutive rows; psi's range and mean, the rigid
    approach rate's range and mean."""
    table = [r for r in equilibrium_table(run, ratio, body, share)
             if r[1] >= t_from]
    if len(table) < 2:
        fail("fewer than two rows at t >= %g" % t_from)
    columns = (("R", 2, 6), ("a", 3, 7), ("a, rays", 10, 7), ("d", 4, 8))
    for name, m, e in columns:
        error = [100 * (r[m] / r[e] - 1) for r in table]
        change = [abs(y - x) for x, y in zip(error, error[1:])]
        print("%-8s %+.2f to %+.2f %%, mean %+.2f %%, mean change between "
              "rows %.2f %%" % (name, min(error), max(error),
                                sum(error) / len(error),
                                sum(change) / len(change)))
    psi = [r[5] for r in table]
    # The angle at which the fitted (far) circles meet the grain boundary's
    # plane, 2 acos(d / 2R): the far shape's dihedral angle, against psi's
    # reading by the near circles.
    far = [2 * math.degrees(math.acos(r[4] / (2 * r[2]))) for r in table]
    rates = [row["approach_rate"] for row in rows(run + "/grain_boundaries.csv")
             if row["time"] >= t_from and math.isfinite(row["approach_rate"])]
    print("psi %.1f to %.1f, mean %.2f; far circles' angle 2 acos(d / 2R) "
          "%.1f to %.1f, mean %.2f; approach rate %+.2f to %+.2f, mean "
          "%+.2f; %d rows from t = %g" %
          (min(psi), max(psi), sum(psi) / len(psi), min(far), max(far),
           sum(far) / len(far), min(rates), max(rates),
           sum(rates) / len(rates), len(table), table[0][1]))


def resting(run, t_from, limit=None):
    rates = {}
    for row in rows(run + "/grain_boundaries.csv"):
        if row["time"] >= t_from and math.isfinite(row["approach_rate"]):
            rates.setdefault(row["step"], row["approach_rate"])
    rates = [rates[step] for step in sorted(rates)]
    if len(rates) < 2:
        fail("fewer than two steps at t >= %g" % t_from)
    change = sum(abs(y - x) for x, y in zip(rates, rates[1:])) / (len(rates) - 1)
    largest = max(abs(u) for u in rates)
    print("resting: approach rate %+.3g to %+.3g, mean change between steps "
          "%.3g, over %d steps from t = %g" %
          (min(rates), max(rates), change, len(rates), t_from))
    if limit is not None and largest > limit:
        fail("|approach rate| reaches %.3g > %g" % (largest, limit))


def row_centroids(run, ratio, grains, out=None, t_from=0, limit=None):
    """A closed row of `grains` grains: per metrics row, the mean over the
    grain boundaries of the rigid centres' distance against the exact
    state's d and of the grains' centroids' distance against the exact
    state's centroids' spacing (row_centroid_spacing), per cent, and the
    centroids' offset from the rigid centres (their distance's
    difference). With `limit`: every row with time >= t_from within the
    relative `limit` of the exact centroids' spacing."""
    metrics = {row["step"]: row for row in rows(run + "/metrics.csv")}
    pairs = rows(run + "/grain_boundaries.csv")
    table = []
    for step in sorted(set(row["step"] for row in pairs) & set(metrics)):
        at = [row for row in pairs if row["step"] == step]
        volume = metrics[step]["solid_volume"]
        rigid = sum(row["centre_distance"] for row in at) / len(at)
        centroid = sum(row["centroid_distance"] for row in at) / len(at)
        table.append((at[0]["time"],
                      100 * (rigid / exact_equilibrium(volume, ratio, 2,
                                                       grains)[2] - 1),
                      100 * (centroid / row_centroid_spacing(volume, ratio,
                                                             grains) - 1),
                      centroid - rigid))
    for r in table:
        print("t = %.4f: rigid centres %+.2f %%, centroids %+.2f %%, offset "
              "%.5f" % r)
    if limit is not None:
        late = [r[2] for r in table if r[0] >= t_from]
        print("centroids' spacing over %d rows at t >= %g: %+.2f to %+.2f %%" %
              (len(late), t_from, min(late), max(late)))
        if not late or max(abs(e) for e in late) > 100 * limit:
            fail("centroids' spacing off by more than %g" % limit)
    if out:
        with open(out, "w") as f:
            f.write("time,rigid_spacing_error_percent,"
                    "centroid_spacing_error_percent,centroid_offset\n")
            for r in table:
                f.write(",".join("%.8g" % v for v in r) + "\n")


def angle(run, ratio, t_from, tolerance_degrees):
    psi = 2 * math.degrees(math.acos(ratio / 2))
    measured = [row["dihedral_angle"] for row in rows(run + "/grain_boundaries.csv")
                if row["time"] >= t_from]
    if not measured:
        fail("no row at t >= %g" % t_from)
    low, high = min(measured), max(measured)
    print("angle: psi %.4g degrees; measured %.4g to %.4g over %d rows at t >= %g"
          % (psi, low, high, len(measured), t_from))
    if not max(abs(low - psi), abs(high - psi)) <= tolerance_degrees:
        fail("dihedral angle off by more than %g degrees" % tolerance_degrees)


def initial(run, radius, tolerance_degrees, tolerance):
    table = [row for row in rows(run + "/grain_boundaries.csv")
             if row["step"] == 0]
    for row in table:
        d = row["centre_distance"]
        psi = 2 * math.degrees(math.acos(d / 2 / radius))
        print("step 0, grains %d-%d: dihedral angle %.4g (exact %.4g), fitted "
              "radius %.6g (%.6g), fitted centre distance %.6g (%.6g)" %
              (row["grain_i"], row["grain_j"], row["dihedral_angle"], psi,
               row["fitted_radius"], radius, row["fitted_centre_distance"], d))
        if not abs(row["dihedral_angle"] - psi) <= tolerance_degrees:
            fail("dihedral angle off by more than %g degrees" % tolerance_degrees)
        if not abs(row["fitted_radius"] - radius) <= tolerance * radius:
            fail("fitted radius off by more than %g" % tolerance)
        if not abs(row["fitted_centre_distance"] - d) <= tolerance * d:
            fail("fitted centre distance off by more than %g" % tolerance)


def disc(run, t_from, tolerance):
    metrics = [row for row in rows(run + "/metrics.csv")
               if row["time"] >= t_from]
    if not metrics:
        fail("no row at t >= %g" % t_from)
    error = [row["interface_area"] / (2 * math.sqrt(math.pi *
                                                     row["solid_volume"])) - 1
             for row in metrics]
    distance = [row["centre_distance"] for row in
                rows(run + "/grain_boundaries.csv") if row["time"] >= t_from]
    print("disc: interface length against 2 sqrt(pi A) %+.3g to %+.3g over %d "
          "rows at t >= %g; rigid centre distance %s" %
          (min(error), max(error), len(error), t_from,
           "%.4g to %.4g" % (min(distance), max(distance)) if distance else
           "- (no grain boundary)"))
    if not max(abs(e) for e in error) <= tolerance:
        fail("the solid is not one disc to %g" % tolerance)


def spacing(run, ratio, grains, d0, column, low, high, out=None):
    """The closed row's centre spacing d = d0 (1 + COLUMN) against the
    exact equilibrium's at each metrics row (the row's solid area): its
    centres' spacing d for the rigid grains, its centroids' spacing for
    the power-cell centroids (centre_distance_change_mean)."""
    centroids = column == "centre_distance_change_mean"
    table = []
    for row in rows(run + "/metrics.csv"):
        if math.isnan(row[column]):
            continue  # the packing analysis' rows only
        if centroids:
            exact = row_centroid_spacing(row["solid_volume"], ratio, grains)
        else:
            exact = exact_equilibrium(row["solid_volume"], ratio, 2, grains)[2]
        table.append((row["time"], d0 * (1 + row[column]), exact))
    t, d, exact = table[-1]
    error = d / exact - 1
    print("t = %g: centre spacing (%s) %.5g, at t = 0 %.5g, exact equilibrium "
          "%.5g: d / d_exact - 1 = %+.4f" % (t, column, d, d0, exact, error))
    if out:
        with open(out, "w") as f:
            f.write("time,centre_spacing,exact_centre_spacing\n")
            for r in table:
                f.write(",".join("%.8g" % v for v in r) + "\n")
    if not low <= error <= high:
        fail("d / d_exact - 1 outside [%g, %g]" % (low, high))


def run_distance(run):
    # The centre distance at t = 0, from grain_boundaries.csv.
    first = rows(run + "/grain_boundaries.csv")[0]
    return first["centre_distance"] / (1 + first["centre_distance_change"])


if __name__ == "__main__":
    mode, args = sys.argv[1], sys.argv[2:]
    # --row N (equilibrium, settled): a closed row of N grains.
    grains = 0
    if "--row" in args:
        k = args.index("--row")
        grains = int(args[k + 1])
        del args[k:k + 2]
    # --share S (equilibrium, settling, swing): the domain's share of the
    # pair.
    share = 1
    if "--share" in args:
        k = args.index("--share")
        share = float(args[k + 1])
        del args[k:k + 2]
    if mode == "law":
        law(args[0], float(args[1]), float(args[2]), int(args[3]), float(args[4]))
    elif mode == "densify":
        densify(args[0], *map(float, args[1:4]))
    elif mode == "centroids":
        centroids(args[0], args[1], float(args[2]), float(args[3]))
    elif mode == "equal":
        equal(args[0], float(args[1]))
    elif mode == "kinetics":
        kinetics(args[0], float(args[1]), float(args[2]), float(args[3]), args[5])
    elif mode == "equilibrium":
        options = dict(zip(args[3::2], args[4::2]))
        equilibrium(args[0], float(args[1]), int(args[2]), options.get("--csv"),
                    share, grains)
    elif mode == "conserved":
        conserved(args[0], float(args[1]))
    elif mode == "settling":
        settling_table(args[0], float(args[1]), args[2:], share)
    elif mode == "bias":
        bias(args[0], float(args[1]), float(args[2]), args[3:])
    elif mode == "settled":
        settled(args[0], float(args[1]), int(args[2]), *map(float, args[3:7]),
                grains=grains)
    elif mode == "angle":
        angle(args[0], *map(float, args[1:4]))
    elif mode == "swing":
        swing(args[0], float(args[1]), int(args[2]), float(args[3]), share)
    elif mode == "resting":
        resting(args[0], float(args[1]),
                    float(args[2]) if len(args) > 2 else None)
    elif mode == "centroids-row":
        options = dict(zip(args[3::2], args[4::2]))
        row_centroids(args[0], float(args[1]), int(args[2]),
                      options.get("--csv"), float(options.get("--from", 0)),
                      float(options["--limit"]) if "--limit" in options
                      else None)
    elif mode == "disc":
        disc(args[0], float(args[1]), float(args[2]))
    elif mode == "initial":
        initial(args[0], *map(float, args[1:4]))
    elif mode == "spacing":
        options = dict(zip(args[7::2], args[8::2]))
        spacing(args[0], float(args[1]), int(args[2]), float(args[3]), args[4],
                float(args[5]), float(args[6]), options.get("--csv"))
    elif mode == "bracket":
        bracket(args[0], args[1], float(args[2]), float(args[3]))
    elif mode == "same":
        same(args[0], args[1], args[2], float(args[3]))
    else:
        fail("unknown mode " + mode)
