#pragma once
// Scene fields as command-line options (--mu-s, --threads, --method, ...). The values are kept
// as the raw text and handed to the library's field table (sb::set_scene_field), so every
// program parses and checks a field the same way, with the same error naming its allowed range.
#include <map>
#include <string>

#include "springblock/scene.hpp"

namespace CLI {
class App;
class Option;
}

namespace sb::shell {

class FieldOptions {
 public:
  // Every field of the table, each with the table's help.
  void add_all(CLI::App* app);
  // One field, with help text that says what it means to this program (and the option, to set
  // its type name in the help).
  CLI::Option* add(CLI::App* app, const std::string& key, const std::string& help);
  // Sets the fields given on the command line, in the table's order (a later field may read an
  // earlier one, e.g. the pattern keeps the layout it finds). Throws sb::InputError.
  void apply(sb::Scene& scene) const;

 private:
  std::map<std::string, std::string> values_;
  CLI::App* app_ = nullptr;
};

// "--" + key with '_' -> '-': the option of a scene-file key.
std::string option_name(const std::string& key);

}  // namespace sb::shell
