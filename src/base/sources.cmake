# Base: error reporting, units, input schemas. Below every layer.
list(APPEND TEHL_SOURCES
  src/base/error.cpp
  src/base/units.cpp
  src/base/number_text.cpp
  src/base/schema.cpp
  src/base/document.cpp
  src/base/document_reader.cpp
  src/base/toml_guard.cpp
)
