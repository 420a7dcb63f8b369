# drive layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/drive/integrator.cpp
  src/drive/torsional_mesh.cpp
  src/drive/torsional_model.cpp
  src/drive/dynamic_response.cpp
)
