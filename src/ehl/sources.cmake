# ehl layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/ehl/grid.cpp
  src/ehl/film_thickness_formulas.cpp
  src/ehl/reynolds_system.cpp
  src/ehl/cross_film.cpp
  src/ehl/film_field.cpp
  src/ehl/anderson_mixer.cpp
  src/ehl/eyring_wall_stress.cpp
  src/ehl/newton_system.cpp
  src/ehl/gmres.cpp
  src/ehl/fixed_point_newton.cpp
  src/ehl/newton_krylov_solver.cpp
  src/ehl/reused_lu_solver.cpp
  src/ehl/line_contact_solver.cpp
  src/ehl/line_contact_pressure.cpp
  src/ehl/line_contact_transient.cpp
  src/ehl/line_contact_coupling.cpp
  src/ehl/elastic_deflection.cpp
  src/ehl/surface_roughness.cpp
  src/ehl/dry_contact.cpp
  src/ehl/surface_temperature.cpp
  src/ehl/film_energy.cpp
  src/ehl/film_energy_system.cpp
  src/ehl/far_history.cpp
  src/ehl/film_augmented_preconditioner.cpp
)
