#pragma once
// A file of JSON lines that grows while a sweep runs (the checkpoint, the partial results, the
// per-unit records): each line goes out with one write() on an O_APPEND descriptor, so a kill
// leaves at most its last line cut short and a reader finds whole lines (a line is complete once
// its '\n' is there). A line is read back by the offset it was written at, which is how the
// coordinator keeps a record on disk instead of in memory. A file closed or destroyed writes the
// lines it holds.
#include <cstddef>
#include <cstdint>
#include <string>

namespace sb::sweep {

class LineFile {
 public:
  // Creates `path` empty, replacing any file of that name. Throws std::runtime_error naming it.
  explicit LineFile(std::string path);
  ~LineFile();
  LineFile(const LineFile&) = delete;
  LineFile& operator=(const LineFile&) = delete;

  // Appends `line` (without its '\n') and returns the offset it starts at.
  std::int64_t append(const std::string& line);
  // Adds `line` to those held for the next flush() (or append), which writes them all with one
  // write(): how a batch of records costs one system call. Returns the offset it will start at.
  std::int64_t hold(const std::string& line);
  void flush();
  std::size_t held_bytes() const { return held_.size(); }
  // The line starting at `offset`, without its '\n' (read from the file, or from the held lines).
  std::string line_at(std::int64_t offset) const;
  void sync();  // flush, then fsync
  // Gives the file a new name (rename(2), atomic); it stays open for appending.
  void rename_to(const std::string& path);
  void remove();  // closes and deletes it
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::int64_t size_ = 0;     // bytes written and held
  std::string held_;          // lines not yet written: the last held_.size() bytes of size_
};

}  // namespace sb::sweep
