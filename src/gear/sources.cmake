# gear layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/gear/stiffness_blank_check.cpp
  src/gear/stiffness_tooth_geometry.cpp
  src/gear/stiffness_tooth_beam.cpp
  src/gear/kuang_yang_stiffness.cpp
  src/gear/potential_energy_stiffness.cpp
  src/gear/iso_stiffness.cpp
  src/gear/mesh_stiffness.cpp
  src/gear/involute.cpp
  src/gear/contact_ratio.cpp
  src/gear/undercut.cpp
  src/gear/gear_pair.cpp
  src/gear/geometry_checks.cpp
  src/gear/path_of_contact.cpp
  src/gear/operating_point.cpp
  src/gear/load_sharing.cpp
  src/gear/tip_relief.cpp
  src/gear/corner_contact.cpp
  src/gear/flank_phase.cpp
  src/gear/mesh_cycle.cpp
  src/gear/tooth_profile.cpp
  src/gear/tooth_blank.cpp
)
