#include "lsp/features/presentation_tokens.hpp"

#include <algorithm>
#include <array>

namespace rung::lsp {
namespace {

using check::query::ClassifiedName;
using check::query::NameClass;

// The legend: indices into these lists are what the tokens carry. Standard LSP names where one
// fits; "global", "input", "output", "inOut" and "instance" are rung's own modifiers.
enum TokenType : uint32_t {
  kNamespace,
  kType,
  kClass,
  kEnum,
  kInterface,
  kStruct,
  kParameter,
  kVariable,
  kProperty,
  kEnumMember,
  kFunction,
  kMethod,
};
constexpr std::array<const char*, 12> kTokenTypes = {"namespace", "type",     "class",    "enum",
                                                     "interface", "struct",   "parameter", "variable",
                                                     "property",  "enumMember", "function", "method"};

enum TokenModifier : uint32_t {
  kDeclaration = 1u << 0,
  kReadonly = 1u << 1,
  kStatic = 1u << 2,
  kDeprecated = 1u << 3,
  kAbstract = 1u << 4,
  kDefaultLibrary = 1u << 5,
  kGlobal = 1u << 6,
  kInput = 1u << 7,
  kOutput = 1u << 8,
  kInOut = 1u << 9,
  kInstance = 1u << 10,
};
constexpr std::array<const char*, 11> kTokenModifiers = {"declaration", "readonly", "static", "deprecated",
                                                         "abstract",    "defaultLibrary", "global", "input",
                                                         "output",      "inOut",    "instance"};

struct Encoded {
  uint32_t type = kVariable;
  uint32_t modifiers = 0;
};

Encoded encode(const ClassifiedName& name) {
  Encoded out;
  switch (name.name_class) {
    case NameClass::Namespace: out.type = kNamespace; break;
    case NameClass::Program:
    case NameClass::FunctionBlock: out.type = kClass; break;
    case NameClass::Interface: out.type = kInterface; break;
    case NameClass::Function: out.type = kFunction; break;
    case NameClass::Method:
    case NameClass::Action: out.type = kMethod; break;
    case NameClass::Property:
    case NameClass::Field: out.type = kProperty; break;
    case NameClass::Struct: out.type = kStruct; break;
    case NameClass::Enum: out.type = kEnum; break;
    case NameClass::Alias: out.type = kType; break;
    case NameClass::Input: out = {kParameter, kInput}; break;
    case NameClass::Output: out = {kParameter, kOutput}; break;
    case NameClass::InOut: out = {kParameter, kInOut}; break;
    case NameClass::Local: out.type = kVariable; break;
    case NameClass::Global: out = {kVariable, kGlobal}; break;
    case NameClass::EnumValue: out.type = kEnumMember; break;
  }
  using namespace check::query;
  const uint16_t flags = name.flags;
  if (flags & kNameDeclaration) out.modifiers |= kDeclaration;
  if (flags & kNameConstant) out.modifiers |= kReadonly;
  if (flags & kNameStatic) out.modifiers |= kStatic;
  if (flags & kNameDeprecated) out.modifiers |= kDeprecated;
  if (flags & kNameAbstract) out.modifiers |= kAbstract;
  if (flags & kNameLibrary) out.modifiers |= kDefaultLibrary;
  if (flags & kNameInstance) out.modifiers |= kInstance;
  return out;
}

}  // namespace

Json semantic_tokens_legend() {
  return Json{{"tokenTypes", kTokenTypes}, {"tokenModifiers", kTokenModifiers}};
}

std::vector<uint32_t> encode_semantic_tokens(const source::LineIndex& lines, const std::vector<ClassifiedName>& names) {
  std::vector<uint32_t> data;
  data.reserve(names.size() * 5);
  uint32_t previous_line = 0;
  uint32_t previous_start = 0;
  for (const ClassifiedName& name : names) {
    const source::Position begin = lines.position_of(name.range.begin);
    const source::Position end = lines.position_of(name.range.end);
    // Names never span lines; a range that does (a broken mapping) is no token.
    if (end.line != begin.line || end.utf16_column <= begin.utf16_column) continue;
    if (begin.line < previous_line || (begin.line == previous_line && begin.utf16_column < previous_start)) continue;
    const Encoded encoded = encode(name);
    data.push_back(begin.line - previous_line);
    data.push_back(begin.line == previous_line ? begin.utf16_column - previous_start : begin.utf16_column);
    data.push_back(end.utf16_column - begin.utf16_column);
    data.push_back(encoded.type);
    data.push_back(encoded.modifiers);
    previous_line = begin.line;
    previous_start = begin.utf16_column;
  }
  return data;
}

Json semantic_token_edits(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after) {
  size_t prefix = 0;
  while (prefix < before.size() && prefix < after.size() && before[prefix] == after[prefix]) ++prefix;
  size_t suffix = 0;
  while (suffix < before.size() - prefix && suffix < after.size() - prefix &&
         before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix]) {
    ++suffix;
  }
  Json edits = Json::array();
  if (prefix == before.size() && prefix == after.size()) return edits;
  // Whole tokens (five integers each) are replaced: clients that patch their token list in place
  // need not split one.
  prefix -= prefix % 5;
  suffix -= suffix % 5;
  edits.push_back(Json{{"start", prefix},
                       {"deleteCount", before.size() - prefix - suffix},
                       {"data", std::vector<uint32_t>(after.begin() + static_cast<std::ptrdiff_t>(prefix),
                                                      after.end() - static_cast<std::ptrdiff_t>(suffix))}});
  return edits;
}

std::string SemanticTokenResults::remember(const std::string& uri, std::vector<uint32_t> data) {
  const uint64_t serial = next_serial_++;
  Entry& entry = entries_[uri];
  entry = Entry{std::to_string(serial), std::move(data), serial};
  if (entries_.size() > kMaxDocuments) {
    const auto oldest = std::min_element(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
      return a.second.serial < b.second.serial;
    });
    entries_.erase(oldest);
  }
  return std::to_string(serial);
}

const std::vector<uint32_t>* SemanticTokenResults::previous(const std::string& uri,
                                                           const std::string& result_id) const {
  const auto found = entries_.find(uri);
  if (found == entries_.end() || found->second.result_id != result_id) return nullptr;
  return &found->second.data;
}

}  // namespace rung::lsp
