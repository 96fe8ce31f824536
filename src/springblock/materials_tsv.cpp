// Materials files: tab-separated columns with a header. Parsed by hand: the format is a header,
// rows of numbers and comment lines, and every message must name the path, line and column.
#include <charconv>
#include <sstream>

#include "springblock/errors.hpp"
#include "springblock/input_file.hpp"
#include "springblock/materials.hpp"

namespace sb {
namespace {

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto tab = line.find('\t', start);
    std::string cell = line.substr(start, tab == std::string::npos ? std::string::npos : tab - start);
    // Surrounding blanks (and a Windows line end) are no part of a value.
    const auto first = cell.find_first_not_of(" \r"), last = cell.find_last_not_of(" \r");
    out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    if (tab == std::string::npos) return out;
    start = tab + 1;
  }
}

bool skipped(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw InputError("materials", "'" + path + "' line " + std::to_string(line) + ": " + what);
}

}  // namespace

BlockMaterials parse_materials_tsv(const std::string& text, const std::string& path) {
  BlockMaterials m;
  m.source = path;
  m.file = true;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<BlockField> header;
  while (std::getline(in, line)) {
    ++line_no;
    if (skipped(line)) continue;
    const auto cells = cells_of(line);
    if (header.empty()) {
      for (const auto& name : cells) {
        const BlockField f = block_field(name, "'" + path + "' line " + std::to_string(line_no) + ", header");
        for (BlockField seen : header)
          if (seen == f) fail(path, line_no, "column '" + name + "' appears twice in the header");
        header.push_back(f);
      }
      continue;
    }
    if (cells.size() != header.size())
      fail(path, line_no, std::to_string(cells.size()) + " cells where the header names " +
                              std::to_string(header.size()) + " columns (cells are separated by tabs)");
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const std::string& cell = cells[k];
      double x = 0;
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
      if (cell.empty() || ec != std::errc() || end != cell.data() + cell.size())
        fail(path, line_no, "column " + std::string(block_field_names()[index_of(header[k])]) + ": '" + cell +
                                "' is not a number");
      m.columns[index_of(header[k])].push_back(x);
    }
    m.lines.push_back(line_no);
  }
  if (header.empty()) throw InputError("materials", "'" + path + "' has no header line naming its columns");
  return m;
}

BlockMaterials read_materials_tsv(const std::string& path) {
  return parse_materials_tsv(read_input_file(path, "materials", "materials file"), path);
}

}  // namespace sb
