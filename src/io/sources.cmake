# io layer sources (one per line, no globbing).
list(APPEND TEHL_SOURCES
  src/io/hdf5_writer.cpp
  src/io/atomic_file.cpp
  src/io/csv_table.cpp
  src/io/script_path.cpp
  src/io/data_dir.cpp
)
