#pragma once
/// \file DeckReader.hpp
/// Reads a Teuchos XML deck. Stricter than Teuchos alone: a number that does not convert in full
/// ("0.01s", "4.5" for an int, "abc") is an error naming the entry, not a silently truncated value.
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "signorini/core/Types.hpp"

namespace signorini::io {

/// Throws core::UserError naming \p path for a missing file, malformed XML, a bad number or a
/// key given twice. Reads the file once (a pipe works).
Teuchos::ParameterList readDeckFile(const std::string& path);
/// The same, collective: rank 0 reads the file and every rank parses its text, so all ranks get
/// the same deck or the same error (another node's missing or different file, stdin under mpirun).
Teuchos::ParameterList readDeckFile(const std::string& path, const Comm& comm);

}  // namespace signorini::io
