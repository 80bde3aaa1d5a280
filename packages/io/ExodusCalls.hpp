#pragma once
/// \file ExodusCalls.hpp
/// The Exodus II library's error handling as the io package uses it (internal: shared by the
/// mesh reader and the series writer, not installed).
#include "signorini/core/Error.hpp"

#include <exodusII.h>

#include <cerrno>
#include <string>

namespace signorini::io::detail {

/// Silences the Exodus library: no messages on stderr, no abort(); errors reach us as return
/// codes and become exceptions.
inline void silenceExodus() { ex_opts(0); }

/// The last message the Exodus library recorded, for error reports; \p code (if given) receives
/// its error code (netCDF passes the system's error on).
inline std::string lastExodusMessage(int* code = nullptr) {
  const char* message = nullptr;
  const char* function = nullptr;
  int recorded = 0;
  ex_get_err(&message, &function, &recorded);
  if (code) *code = recorded;
  std::string text;
  if (function && *function) text += std::string(function) + ": ";
  if (message && *message) text += message;
  return text;
}

/// Throws a UserError naming the file when an Exodus call failed (negative status), with
/// a hint when the system said the disk, the quota or the file size limit is full (ENOSPC, EDQUOT,
/// EFBIG).
inline void checkExodus(int status, const char* call, const std::string& path) {
  if (status < 0) {
    int code = 0;
    const std::string message = lastExodusMessage(&code);
    const bool full = code == ENOSPC || code == EDQUOT || code == EFBIG;
    SIGNORINI_USER_ERROR("Exodus II file '" << path << "': " << call << " failed (" << message << ")"
                                            << (full ? " (disk full, quota or file size limit exceeded?)" : ""));
  }
}

}  // namespace signorini::io::detail
