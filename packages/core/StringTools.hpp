#pragma once
/// \file StringTools.hpp
/// Small string tests shared by the packages (file names, suffixes).
#include <string>

namespace signorini::core {

/// Whether \p text ends with \p suffix (C++20's ends_with; this code is C++17).
inline bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace signorini::core
