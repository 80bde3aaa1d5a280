#pragma once
/// \file Error.hpp
/// User errors (bad input: reported with a clear message and a non-zero exit) versus
/// programming invariants (assertions).
#include <sstream>
#include <stdexcept>
#include <string>

namespace signorini::core {

/// Thrown for bad user input (deck, mesh file, command line, output directory).
/// The message names the file, key or element at fault; the driver prints it and exits non-zero.
class UserError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown when an iterative method does not reach its tolerance (a run-time failure, not a bug).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// \p what without a leading "<source file>:<line>:" line and the "Throw number = n" and "Throw
/// test that evaluated to true: ..." paragraphs that Teuchos' exception macros put before the
/// message: the user needs the message, not the library's source location.
inline std::string withoutSourceLocation(const std::string& what) {
  const auto newline = what.find('\n');
  if (newline == std::string::npos || newline == 0 || what[newline - 1] != ':') return what;
  const std::string first = what.substr(0, newline);
  if (first.find(".cpp:") == std::string::npos && first.find(".hpp:") == std::string::npos) return what;
  auto start = what.find_first_not_of('\n', newline);
  while (start != std::string::npos &&
         (what.compare(start, 15, "Throw number = ") == 0 || what.compare(start, 35, "Throw test that evaluated to true: ") == 0)) {
    const auto end = what.find("\n\n", start);
    start = end == std::string::npos ? end : what.find_first_not_of('\n', end);
  }
  return start == std::string::npos ? what : what.substr(start);
}

}  // namespace signorini::core

/// Throw a signorini::core::UserError whose message is built with operator<<.
#define SIGNORINI_USER_ERROR(streamed)                    \
  do {                                                    \
    std::ostringstream signorini_os_;                     \
    signorini_os_ << streamed;                            \
    throw ::signorini::core::UserError(signorini_os_.str()); \
  } while (0)

/// Programming invariant: violated only by a bug in signorini itself.
#define SIGNORINI_ASSERT(cond, streamed)                                                \
  do {                                                                                  \
    if (!(cond)) {                                                                      \
      std::ostringstream signorini_os_;                                                 \
      signorini_os_ << __FILE__ << ":" << __LINE__ << ": internal error: assertion '"   \
                    << #cond << "' failed: " << streamed;                               \
      throw std::logic_error(signorini_os_.str());                                      \
    }                                                                                   \
  } while (0)
