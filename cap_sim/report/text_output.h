#pragma once
// Writes a text output (JSON report, trace) under a temporary name and renames it
// on success, so a failed run never leaves a half-written file.

#include "capsim/system/pending_file.h"

#include <string>

namespace capsim::sim {

// Throws std::runtime_error with the path and the reason on failure.
void write_text_file(const std::string& path, const std::string& text);

// The same into a pending file, which the caller commits; messages name its
// target.
void write_text_file(PendingFile& out, const std::string& text);

}  // namespace capsim::sim
