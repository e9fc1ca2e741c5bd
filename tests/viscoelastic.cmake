# --- Viscoelastic melts: the conformation models (viscoelastic seed) ------
add_executable(conformation_models conformation_models.cc)
target_link_libraries(conformation_models levelsinter_lib)
deal_ii_setup_target(conformation_models)

# Closed forms in homogeneous flows, each in the direct and the
# log-conformation form; the limits are in the driver. RK4 at 1000 steps per
# relaxation time; measured errors: Oldroyd-B shear / extension 5e-15,
# Giesekus steady shear (eta, Psi1, Psi2 at Wi 0.1, 1, 10) 1.6e-11 direct,
# 1.8e-13 log, relaxation 2e-14; XPP linear limit 9.9e-7 (the O(Wi^2)
# nonlinearity at Wi = 1e-3, limit 1e-5); direct against log 5.5e-13
# (Giesekus) and 1.7e-13 (XPP) at Wi 5 in shear and 2 in extension.
foreach(form direct log)
  foreach(case shear-oldroyd extension-oldroyd shear-giesekus relax-giesekus
          linear-xpp)
    add_test(NAME conformation_${case}_${form}
      COMMAND conformation_models ${case} ${form})
  endforeach()
endforeach()
foreach(case forms-giesekus forms-xpp)
  add_test(NAME conformation_${case} COMMAND conformation_models ${case})
endforeach()
