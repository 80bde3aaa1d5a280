#pragma once
/// \file DeckReader.hpp
/// Reads a Teuchos XML deck. Stricter than Teuchos alone: a number that does not convert in full
/// ("0.01s", "4.5" for an int, "abc") is an error naming the entry, not a silently truncated value.
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace signorini::io {

/// Throws core::UserError naming \p path for a missing file, malformed XML or a bad number.
Teuchos::ParameterList readDeckFile(const std::string& path);

}  // namespace signorini::io
