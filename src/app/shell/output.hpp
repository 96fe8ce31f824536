#pragma once
// Output files of a run: refused before the run when they could not be written after it (not
// after minutes of simulation), then written whole or not at all (sb::write_file_atomic: a
// temporary file renamed over the target), so an interrupt or a failure leaves no partial file
// and an existing file untouched.
#include <string>

namespace sb::shell {

// Throws sb::InputError(field) naming `path` when it cannot be written (missing or unwritable
// directory, a directory given as the file). Leaves nothing behind.
void claim_output(const std::string& path, const std::string& field);

// Creates directory `dir` and its parents for outputs (an empty directory is no partial result);
// sb::InputError(field) naming it when that fails.
void make_output_directory(const std::string& dir, const std::string& field);

// Writes `content` to `path` atomically.
void write_output(const std::string& path, const std::string& content);

}  // namespace sb::shell
