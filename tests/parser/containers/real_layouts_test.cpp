// Container files written after the layouts vendors really produce parse without a
// syntax diagnostic: the reader's virtual text is what the grammar accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "container_test_support.hpp"
#include "parser/document.hpp"

namespace rung::containers {
namespace {

std::string raw_data(const std::string& name) {
  std::ifstream in(testing::data_path(name), std::ios::binary);
  EXPECT_TRUE(in) << "missing test data " << name;
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

class ContainerRealLayout : public ::testing::TestWithParam<const char*> {};

TEST_P(ContainerRealLayout, ParsesWithoutDiagnostics) {
  const std::string name = GetParam();
  const Document doc = Document::from_bytes(name, raw_data(name));
  ASSERT_NE(doc.container(), nullptr);
  ASSERT_NE(doc.tree(), nullptr);
  for (const Diagnostic& d : doc.diagnostics()) {
    const FilePosition p = doc.position_of_file_offset(d.range.begin);
    ADD_FAILURE() << name << ":" << p.line << ":" << p.column << ": " << d.code << " " << d.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Data, ContainerRealLayout,
                         ::testing::Values("P_Sequence.TcPOU", "I_Parent.TcIO", "FB_Client.EXP"));

}  // namespace
}  // namespace rung::containers
