# gear layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/gear/stiffness_blank_check.cpp
  src/gear/stiffness_tooth_geometry.cpp
  src/gear/stiffness_tooth_beam.cpp
  src/gear/kuang_yang_stiffness.cpp
  src/gear/potential_energy_stiffness.cpp
  src/gear/iso_stiffness.cpp
  src/gear/mesh_stiffness.cpp
)
