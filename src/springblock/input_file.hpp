#pragma once
// Files the user names (a scene, a materials table, a sweep, a mask), read so that a missing
// file, a directory or a failed read is bad input (an InputError naming the field: exit 2), not
// an internal error.
#include <functional>
#include <string>
#include <string_view>

namespace sb {

// The file's bytes in order, a chunk at a time, to `take` (which may throw to stop early: a
// reader that refuses what it sees reads no further). `what` names the file in the messages
// ("scene file", "mask file", ...): "cannot read <what> '<path>': <reason>".
void read_input_chunks(const std::string& path, const std::string& field, const std::string& what,
                       const std::function<void(std::string_view)>& take);

// The whole text, refused beyond 1 GiB (a device or pipe that never ends).
std::string read_input_file(const std::string& path, const std::string& field, const std::string& what);

}  // namespace sb
