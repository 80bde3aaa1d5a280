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
