#include "shell/field_options.hpp"

#include <CLI/CLI.hpp>

#include "springblock/scene_fields.hpp"

namespace sb::shell {

std::string option_name(const std::string& key) {
  std::string o = key;
  for (auto& ch : o)
    if (ch == '_') ch = '-';
  return "--" + o;
}

void FieldOptions::add_all(CLI::App* app) {
  for (const auto& f : sb::scene_fields()) add(app, f.key, f.help + " (e.g. " + f.example + ")");
}

CLI::Option* FieldOptions::add(CLI::App* app, const std::string& key, const std::string& help) {
  app_ = app;
  return app->add_option(option_name(key), values_[key], help);
}

void FieldOptions::apply(sb::Scene& scene) const {
  for (const auto& f : sb::scene_fields())
    if (values_.count(f.key) > 0 && app_->count(option_name(f.key)) > 0) sb::set_scene_field(scene, f.key, values_.at(f.key));
}

}  // namespace sb::shell
