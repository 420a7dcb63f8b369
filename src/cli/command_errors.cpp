// The report of a runner's error, shared by main() and the ranks of `tehl sweep`.
#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "tehl/error.hpp"

namespace tehl::cli {

CommandError DescribeCommandError(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const tehl::InputError& e) {
    return {kExitBadInput, e.what()};
  } catch (const std::filesystem::filesystem_error& e) {
    // Result folders and files come from -o/--output-dir or [output] directory and name.
    return {kExitBadInput,
            "tehl: cannot write the results: " + e.code().message() + ": " + e.path1().string() +
                " (allowed: a folder that can be created and written; see -o/--output-dir "
                "and [output] directory)"};
  } catch (const std::exception& e) {
    return {kExitInternal, std::string("tehl: internal error: ") + e.what()};
  } catch (...) {
    return {kExitInternal, "tehl: internal error: an exception of unknown type"};
  }
}

}  // namespace tehl::cli
