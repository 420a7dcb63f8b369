# lubricant layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/lubricant/law_check.cpp
  src/lubricant/viscosity_model.cpp
  src/lubricant/density_model.cpp
  src/lubricant/roelands_viscosity.cpp
  src/lubricant/roelands_gamma_viscosity.cpp
  src/lubricant/barus_viscosity.cpp
  src/lubricant/constant_viscosity.cpp
  src/lubricant/dowson_higginson_density.cpp
  src/lubricant/constant_density.cpp
  src/lubricant/pressure_dependent_conductivity.cpp
  src/lubricant/constant_conductivity.cpp
  src/lubricant/model_factory.cpp
  src/lubricant/lubricant_schema.cpp
  src/lubricant/lubricant.cpp
  src/lubricant/lubricant_reader.cpp
)
