#pragma once
/// \file StringTools.hpp
/// Small string tests shared by the packages (file names, suffixes, deck lists).
#include <cmath>
#include <string>
#include <vector>

namespace signorini::core {

/// Whether \p text ends with \p suffix (C++20's ends_with; this code is C++17).
inline bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// \p text without the blanks (spaces, tabs, line ends) at either end.
inline std::string trim(const std::string& text) {
  const auto b = text.find_first_not_of(" \t\n\r");
  if (b == std::string::npos) return "";
  return text.substr(b, text.find_last_not_of(" \t\n\r") - b + 1);
}

/// The items of the \p separator-separated \p text, each trimmed, empty ones included ("a,,b"
/// and "a," have an empty item): the deck lists' callers refuse them by name.
inline std::vector<std::string> splitTrimmed(const std::string& text, char separator) {
  std::vector<std::string> items;
  for (size_t start = 0;;) {
    const auto at = text.find(separator, start);
    items.push_back(trim(text.substr(start, at == std::string::npos ? std::string::npos : at - start)));
    if (at == std::string::npos) return items;
    start = at + 1;
  }
}

/// A value that is not finite as "nan", "inf" or "-inf" (glibc prints "-nan" for some NaNs; the
/// sign of a NaN means nothing to a user).
inline std::string nonFiniteText(double value) { return std::isnan(value) ? "nan" : value < 0 ? "-inf" : "inf"; }

}  // namespace signorini::core
