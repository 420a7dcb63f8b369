# ehl layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/ehl/elastic_deflection.cpp
  src/ehl/surface_roughness.cpp
  src/ehl/dry_contact.cpp
)
