# lubricant layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
)
