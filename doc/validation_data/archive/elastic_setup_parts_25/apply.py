# Throw-away instrumentation of SolidElasticStokes::setup_solid_system (per rank, wall per part).
p='/work/main/source/mechanics/solid_elastic_stokes.cc'
s=open(p).read()
s=s.replace("#include <algorithm>\n","#include <algorithm>\n#include <chrono>\n#include <cstdio>\n",1)
s=s.replace("""  void
  SolidElasticStokes<dim>::setup_solid_system()
  {
    solid_dofs.distribute_dofs(fe_collection);""","""  void
  SolidElasticStokes<dim>::setup_solid_system()
  {
    auto t0 = std::chrono::steady_clock::now();
    const unsigned int me = Utilities::MPI::this_mpi_process(solid_dofs.get_communicator());
    auto lap = [&](const char *what) {
      const auto t1 = std::chrono::steady_clock::now();
      std::fprintf(stderr, "SETUP rank %u %s %.3f\\n", me, what, std::chrono::duration<double>(t1 - t0).count());
      t0 = t1;
    };
    solid_dofs.distribute_dofs(fe_collection);
    lap("distribute_dofs");""")
s=s.replace("""    const auto     n        = number_by_blocks(solid_dofs);
    const IndexSet owned    = solid_dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(solid_dofs);""","""    const auto     n        = number_by_blocks(solid_dofs);
    lap("renumber");
    const IndexSet owned    = solid_dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(solid_dofs);
    lap("relevant");""")
s=s.replace("""    constraints.close();
    velocity_modes = rigid_body_modes(solid_dofs, owned_partitioning[0]);""","""    constraints.close();
    lap("constraints");
    velocity_modes = rigid_body_modes(solid_dofs, owned_partitioning[0]);
    lap("modes");""")
s=s.replace("""      DoFTools::make_sparsity_pattern(solid_dofs,
                                      coupling,
                                      dsp,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));""","""      DoFTools::make_sparsity_pattern(solid_dofs,
                                      coupling,
                                      dsp,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));
      lap("cell pattern");""")
s=s.replace("""      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      matrix.reinit(owned_partitioning, dsp, comm);
    };""","""      lap("face pattern");
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      lap("distribute pattern");
      matrix.reinit(owned_partitioning, dsp, comm);
      lap("matrix reinit");
    };""")
s=s.replace("""    solid_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
    solid_dofs_current = true;""","""    solid_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
    lap("vectors");
    solid_dofs_current = true;""")
open(p,'w').write(s)
print(s.count('lap("'))
