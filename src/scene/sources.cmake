# Scene layer: reads case files, decides which effects run, drives a mesh cycle or a sweep.
list(APPEND TEHL_SOURCES
  src/scene/case_schema.cpp
  src/scene/case_reader.cpp
  src/scene/case_inputs.cpp
  src/scene/case_plan.cpp
  src/scene/film_case.cpp
  src/scene/automatic_grid.cpp
  src/scene/contact_case.cpp
  src/scene/contact_scene.cpp
  src/scene/contact_csv.cpp
  src/scene/gear_case.cpp
  src/scene/dynamic_load.cpp
  src/scene/mesh_cycle_output.cpp
  src/scene/mesh_cycle_checkpoint.cpp
  src/scene/mesh_cycle_checkpoint_reader.cpp
  src/scene/checkpoint_codec.cpp
  src/scene/mesh_cycle_plan.cpp
  src/scene/profile_memory.cpp
  src/scene/mesh_cycle_scene.cpp
  src/scene/step_restart.cpp
  src/scene/study_case_text.cpp
  src/scene/study_reader.cpp
  src/scene/study.cpp
  src/scene/study_index.cpp
  src/scene/scene_row_reader.cpp
  src/scene/study_run.cpp
)
