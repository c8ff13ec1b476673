// Helpers shared by the container tests: reading data files and asking where a
// piece of virtual text lands in the container file.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "parser/containers/container_document.hpp"
#include "parser/source/decode.hpp"
#include "parser/source/line_index.hpp"
#include "tests/support/test_paths.hpp"

namespace rung::containers::testing {

inline std::string data_path(std::string_view name) {
  return rung::test::source_dir().string() + "/tests/parser/containers/data/" + std::string(name);
}

// The file's decoded text, as a reader receives it.
inline std::string decoded_data(std::string_view name) {
  std::ifstream in(data_path(name), std::ios::binary);
  EXPECT_TRUE(in) << "missing test data " << name;
  std::stringstream bytes;
  bytes << in.rdbuf();
  return source::decode(bytes.str()).utf8;
}

struct LineColumn {
  uint32_t line;    // 1-based, as an editor shows it
  uint32_t column;  // 1-based, in characters

  friend bool operator==(const LineColumn&, const LineColumn&) = default;
  friend std::ostream& operator<<(std::ostream& out, const LineColumn& lc) {
    return out << lc.line << ":" << lc.column;
  }
};

// Where the virtual text's first occurrence of `needle` (from `from`) lands in the file.
inline LineColumn file_position_of(const ContainerDocument& doc, std::string_view file_text, std::string_view needle,
                                   size_t from = 0) {
  const size_t at = doc.virtual_text.find(needle, from);
  EXPECT_NE(at, std::string::npos) << "'" << needle << "' not in the virtual text";
  if (at == std::string::npos) return {0, 0};
  const auto file_offset = doc.to_file_offset(static_cast<uint32_t>(at));
  EXPECT_TRUE(file_offset.has_value());
  if (!file_offset) return {0, 0};
  EXPECT_EQ(file_text.substr(*file_offset, needle.size()), needle) << "mapped to the wrong bytes";
  const source::Position p = source::LineIndex(file_text).position_of(*file_offset);
  return {p.line + 1, p.char_column + 1};
}

}  // namespace rung::containers::testing
