#include "parser/file_walk.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

#include "parser/containers/plcopen_reader.hpp"

namespace rung {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool skipped_directory(const std::filesystem::path& dir) {
  std::string name = dir.filename().string();
  if (name.size() > 1 && name[0] == '.') return true;
  return name == "build" || name == "node_modules" || name == "_Boot" || name == "_CompileInfo";
}

}  // namespace

SourceKind source_kind_of(const std::filesystem::path& path) {
  std::string ext = lower(path.extension().string());
  if (ext == ".st" || ext == ".iecst" || ext == ".gvl" || ext == ".pou" || ext == ".dut")
    return SourceKind::StructuredText;
  if (ext == ".il") return SourceKind::InstructionList;
  if (ext == ".sfc") return SourceKind::Sfc;
  if (ext == ".tcpou" || ext == ".tcdut" || ext == ".tcgvl" || ext == ".tcio" || ext == ".tcitf")
    return SourceKind::TwinCat;
  if (ext == ".exp") return SourceKind::CodesysExport;
  if ((ext == ".xml" || ext == ".plcopen") && is_plcopen_file(path)) return SourceKind::PlcOpenXml;
  return SourceKind::None;
}

bool is_plcopen_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string head(8192, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  return containers::looks_like_plcopen(head);
}

WalkResult collect_source_files(const std::vector<std::filesystem::path>& inputs) {
  namespace fs = std::filesystem;
  WalkResult result;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    fs::file_status status = fs::status(input, ec);
    if (ec || !fs::exists(status)) {
      result.errors.push_back(input.string() + ": no such file or directory");
      continue;
    }
    if (!fs::is_directory(status)) {
      result.files.push_back(input);
      continue;
    }
    fs::recursive_directory_iterator it(input, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
      result.errors.push_back(input.string() + ": cannot list directory: " + ec.message());
      continue;
    }
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (ec) {
        result.errors.push_back(input.string() + ": " + ec.message());
        break;
      }
      const fs::directory_entry& entry = *it;
      std::error_code type_ec;
      if (entry.is_directory(type_ec)) {
        if (skipped_directory(entry.path())) it.disable_recursion_pending();
        continue;
      }
      if (entry.is_regular_file(type_ec) && source_kind_of(entry.path()) != SourceKind::None) {
        result.files.push_back(entry.path());
      }
    }
  }
  std::sort(result.files.begin(), result.files.end());
  result.files.erase(std::unique(result.files.begin(), result.files.end()), result.files.end());
  return result;
}

}  // namespace rung
