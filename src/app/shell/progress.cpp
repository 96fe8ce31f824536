#include "shell/progress.hpp"

#include <cstdio>

namespace sb::shell {
namespace {
bool g_line_open = false;
}  // namespace

void show_progress(const std::string& text) {
  std::fprintf(stderr, "\r%s   ", text.c_str());
  std::fflush(stderr);
  g_line_open = true;
}

void end_progress_line() {
  if (!g_line_open) return;
  std::fprintf(stderr, "\n");
  g_line_open = false;
}

double eta_seconds(double fraction, double elapsed_s) { return elapsed_s * (1 - fraction) / fraction; }

std::string format_seconds(double s) {
  char buf[32];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1fmin", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1fh", s / 3600);
  return buf;
}

}  // namespace sb::shell
