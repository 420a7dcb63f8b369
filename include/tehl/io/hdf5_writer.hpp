// One HDF5 result file, written atomically: everything goes to `<path>.part` and the file is
// renamed to `<path>` only by Commit(), so a run that is killed or fails leaves no file under
// the final name (a stale `.part` at most). Every numeric dataset carries a `unit` attribute
// ("m", "Pa", "-" for dimensionless, "s" ...) and a `meaning` attribute; every value written
// is checked first: a NaN or Inf is refused with NonFiniteError naming the dataset and index.
// Layout of tehl's results: docs/results.md. hdf5.h stays in src/io/hdf5_writer.cpp.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tehl {

// Thrown before anything non-finite reaches a file.
class NonFiniteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Hdf5Writer {
 public:
  // Creates `<final_path>.part` (and the parent folder); throws std::runtime_error when the
  // file cannot be created.
  explicit Hdf5Writer(const std::string& final_path);
  ~Hdf5Writer();  // without Commit(): closes and removes the .part file
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Dataset paths are absolute ("/cycle/h_min"); missing groups are created.
  // A 1-D array of doubles with its unit and meaning.
  void WriteVector(const std::string& dataset,
                   const std::vector<double>& values,
                   const std::string& unit,
                   const std::string& meaning);
  // A 2-D array, row-major (rows x cols), e.g. p over (step, x).
  void WriteMatrix(const std::string& dataset,
                   const std::vector<double>& row_major,
                   int rows,
                   int cols,
                   const std::string& unit,
                   const std::string& meaning);
  // A 1-D array of integers (counts; unit "-").
  void WriteInts(const std::string& dataset,
                 const std::vector<int>& values,
                 const std::string& meaning);
  // A 1-D array of variable-length UTF-8 strings.
  void WriteStrings(const std::string& dataset,
                    const std::vector<std::string>& values,
                    const std::string& meaning);
  // A scalar variable-length string (e.g. the case text).
  void WriteText(const std::string& dataset, const std::string& text, const std::string& meaning);
  // A string attribute on a group or dataset that exists ("/" for the file).
  void SetAttribute(const std::string& object, const std::string& name, const std::string& value);
  // A double attribute with its unit in the attribute `<name>_unit`.
  void SetAttribute(const std::string& object,
                    const std::string& name,
                    double value,
                    const std::string& unit);
  // An integer attribute (a count: 64-bit signed), its unit in `<name>_unit` ("-").
  void SetIntAttribute(const std::string& object, const std::string& name, long long value);

  // Flushes, closes and renames `<final_path>.part` to `<final_path>`. Throws
  // std::runtime_error when that fails. Nothing may be written afterwards.
  void Commit();

  const std::string& final_path() const;
  std::string temporary_path() const;  // final_path() + ".part"

 private:
  // A scalar attribute of file type `file_type` from `value` in `memory_type` (hid_t values),
  // with its unit in `<name>_unit`.
  void SetScalarAttribute(const std::string& object,
                          const std::string& name,
                          long long file_type,
                          long long memory_type,
                          const void* value,
                          const std::string& unit);
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// Throws NonFiniteError("<dataset>[<index>] = nan: ...") at the first non-finite value.
void CheckFinite(const std::string& dataset, const std::vector<double>& values);

}  // namespace tehl
