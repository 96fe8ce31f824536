#pragma once
// The whole text of a file the user names (a scene, a materials table, a sweep), or an InputError
// naming the field: a missing file, a directory or a failed read is bad input (exit 2), not an
// internal error.
#include <string>

namespace sb {

// `what` names the file in the message ("scene file", "materials file", ...).
std::string read_input_file(const std::string& path, const std::string& field, const std::string& what);

}  // namespace sb
