// libFuzzer target: the input path of `tehl case --check` and of `tehl lubricant FILE`.
//
// Every input is read twice:
//  1. as a case file, exactly as `tehl case --check` does it (src/cli/case_command.cpp): the
//     text -> Document (TOML + case schema) -> cross-key rules (ReadCaseDocument) -> gear
//     reader (geometry, stiffness, dynamic load) -> film reader (lubricant file, effects,
//     numerics, surfaces) -> the run's plan (a gear case's steps and grid, a contact case's
//     grid, automatic or given). The text is handed over through an anonymous in-memory file
//     (memfd), so ReadCaseDocument's file path is the one the program runs, NUL check
//     included, without touching the disk;
//  2. as a lubricant file, through Lubricant::FromString (schema, laws built by the factory).
//
// An InputError is the normal answer to bad input. Anything else is a finding: a crash, an
// AddressSanitizer or UndefinedBehaviorSanitizer report, any other exception escaping (the
// program would exit 3, "internal error"), or a hang (libFuzzer -timeout).
//
// Build and run: tests/fuzz/README.md (scripts/ci_extra.sh runs it for 60 s in CI).
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/case_plan.hpp"
#include "scene/case_reader.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace {

// An anonymous in-memory file; "/proc/self/fd/<n>" opens it like any case file.
class MemoryFile {
 public:
  MemoryFile() : fd_(memfd_create("fuzz_case.toml", 0)) {
    if (fd_ < 0) {
      std::perror("memfd_create");
      std::abort();
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  const std::string& Write(const uint8_t* data, size_t size) {
    if (ftruncate(fd_, 0) != 0 || pwrite(fd_, data, size, 0) != static_cast<ssize_t>(size)) {
      std::perror("memfd write");
      std::abort();
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

// `tehl case --check FILE` minus the printing (src/cli/case_command.cpp).
void CheckCase(const std::string& path) {
  using namespace tehl::internal;
  try {
    Document doc = ReadCaseDocument(path);
    CheckCasePlan(doc);
    doc.ThrowIfProblems();
  } catch (const tehl::InputError&) {
    // Bad input, reported with file:line: the expected outcome.
  }
}

// `tehl lubricant FILE`: the lubricant reader.
void CheckLubricant(const std::string& text) {
  try {
    tehl::Lubricant::FromString(text, "fuzz_lubricant.toml");
  } catch (const tehl::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static MemoryFile file;
  CheckCase(file.Write(data, size));
  CheckLubricant(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
