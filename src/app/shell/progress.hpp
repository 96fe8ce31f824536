#pragma once
// The progress line on stderr: redrawn in place with '\r' while a run goes on, ended before any
// other message so that message starts on its own line. stderr is one per process, so whether a
// line is open is process-wide state, not an object's.
#include <string>

namespace sb::shell {

// Redraws the progress line as `text` (padded, so a shorter text covers a longer one).
void show_progress(const std::string& text);

// Ends the progress line if one is open (prints the newline); otherwise does nothing.
void end_progress_line();

// Seconds left when `fraction` of the work took `elapsed_s`, at the same rate. Needs fraction > 0.
double eta_seconds(double fraction, double elapsed_s);

// 42s, 3.5min, 2.1h: a duration at the precision a person reads it.
std::string format_seconds(double s);

}  // namespace sb::shell
