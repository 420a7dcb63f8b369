# drive layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/drive/integrator.cpp
  src/drive/torsional_mesh.cpp
  src/drive/torsional_model.cpp
  src/drive/dynamic_response.cpp
  src/drive/dynamic_sweep.cpp
  src/drive/gear_train.cpp
  src/drive/train_mesh_rows.cpp
  src/drive/train_groups.cpp
  src/drive/gear_train_tabulation.cpp
  src/drive/train_torques.cpp
  src/drive/planet_design.cpp
  src/drive/dc_motor.cpp
  src/drive/motor_schema.cpp
  src/drive/train_schema.cpp
  src/drive/train_reader.cpp
  src/drive/train_checks.cpp
)
