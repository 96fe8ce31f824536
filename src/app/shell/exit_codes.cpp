#include "shell/exit_codes.hpp"

#include <cstdio>
#include <exception>

#include "shell/progress.hpp"
#include "springblock/errors.hpp"

namespace sb::shell {

int guarded(const std::string& program, const std::function<int()>& body, const OtherFailure& other) {
  try {
    return body();
  } catch (const sb::InputError& e) {
    end_progress_line();
    // what() already starts with the field name: "pattern: unknown pattern kind ..."
    std::fprintf(stderr, "%s: invalid %s\n", program.c_str(), e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    end_progress_line();
    std::fprintf(stderr, "%s: %s: %s\n", program.c_str(), other.label.c_str(), e.what());
    return other.code;
  }
}

}  // namespace sb::shell
