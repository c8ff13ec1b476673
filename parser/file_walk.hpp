// Finding PLC source files: `rung parse DIR` walks directories for every file kind rung reads.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rung {

enum class SourceKind { None, StructuredText, InstructionList, Sfc, TwinCat, CodesysExport, PlcOpenXml };

// By extension, case-insensitive: .st .iecst .il .sfc .gvl .pou .TcPOU .TcDUT .TcGVL .TcIO .TcITF .EXP.
// An .xml file is PLCopen XML only if its content says so: see is_plcopen_file().
SourceKind source_kind_of(const std::filesystem::path& path);

// Whether an .xml file is a PLCopen XML project (its root names the TC6 namespace); reads only
// the first few KB.
bool is_plcopen_file(const std::filesystem::path& path);

struct WalkResult {
  std::vector<std::filesystem::path> files;  // sorted, no duplicates
  std::vector<std::string> errors;           // paths that do not exist or cannot be listed
};

// Files named explicitly are taken whatever their extension; directories are walked recursively
// for known kinds (and .xml files that are PLCopen projects), skipping hidden folders and build
// output (.git, build, node_modules).
WalkResult collect_source_files(const std::vector<std::filesystem::path>& inputs);

}  // namespace rung
