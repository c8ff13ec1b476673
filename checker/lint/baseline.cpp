#include "checker/lint/baseline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "checker/symbols/file_symbols.hpp"
#include "checker/symbols/names.hpp"

namespace rung::lint {
namespace {

constexpr int kVersion = 1;

// The declaration around `tree_offset`: the innermost POU, member, type or global list.
std::string enclosing_name(const check::FileSymbols& symbols, uint32_t tree_offset) {
  const check::Symbol* best = nullptr;
  auto consider = [&](const check::Symbol* symbol) {
    if (!symbol || symbol->node.is_null()) return;
    if (symbol->node.begin() > tree_offset || tree_offset >= symbol->node.end()) return;
    if (!best || symbol->node.begin() >= best->node.begin()) best = symbol;
  };
  for (const check::Symbol* symbol : symbols.top_level) consider(symbol);
  for (const check::Symbol* symbol : check::pous_of(symbols)) consider(symbol);
  if (!best) return {};
  std::string name(best->name);
  for (const check::Symbol* owner = best->owner; owner; owner = owner->owner) {
    name.insert(0, std::string(owner->name) + ".");
  }
  return name;
}

// The line's text without blanks, upper-cased, hashed: indentation, reformatting and keyword case
// do not change it; moving the line does not either.
std::string line_fingerprint(const Document& document, uint32_t offset) {
  const FilePosition at = document.position_of_file_offset(offset);
  const source::LineIndex& lines = document.file_lines();
  std::string packed;
  if (at.line >= 1 && at.line - 1 < lines.line_count()) {
    const std::string_view text = document.file_text();
    const uint32_t begin = lines.line_start(at.line - 1);
    const uint32_t end = lines.line_end(at.line - 1);
    for (uint32_t i = begin; i < end && i < text.size(); ++i) {
      const char c = text[i];
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '\f' && c != '\v') packed += c;
    }
  }
  return fmt::format("{:016x}", static_cast<uint64_t>(check::NameHash{}(packed)));
}

using Key = std::tuple<std::string, std::string, std::string, std::string>;
Key key_of(const BaselineEntry& entry) {
  return {entry.path, entry.code, entry.pou, entry.fingerprint};
}

}  // namespace

std::string baseline_path(const std::string& file, const std::filesystem::path& root) {
  const std::filesystem::path path = std::filesystem::absolute(file).lexically_normal();
  std::filesystem::path relative = path.lexically_relative(std::filesystem::absolute(root).lexically_normal());
  if (relative.empty() || *relative.begin() == "..") relative = path;
  return relative.generic_string();
}

BaselineEntry baseline_entry(const check::Workspace& workspace, const FileFindings& file, const Finding& finding,
                             const std::filesystem::path& root) {
  const check::Source& source = workspace.model().source(file.source);
  const Document& document = *source.document;
  BaselineEntry entry;
  entry.path = baseline_path(file.path, root);
  entry.code = finding.diagnostic.code;
  if (std::optional<uint32_t> tree_offset = document.tree_offset_of(finding.diagnostic.range.begin)) {
    entry.pou = enclosing_name(source.symbols, *tree_offset);
  }
  entry.fingerprint = line_fingerprint(document, finding.diagnostic.range.begin);
  entry.message = finding.diagnostic.message;
  return entry;
}

std::string baseline_json(std::vector<BaselineEntry> entries) {
  std::sort(entries.begin(), entries.end(), [](const BaselineEntry& a, const BaselineEntry& b) {
    return std::tie(a.path, a.code, a.pou, a.fingerprint, a.message) <
           std::tie(b.path, b.code, b.pou, b.fingerprint, b.message);
  });
  nlohmann::json findings = nlohmann::json::array();
  for (const BaselineEntry& entry : entries) {
    findings.push_back({{"path", entry.path},
                        {"code", entry.code},
                        {"pou", entry.pou},
                        {"fingerprint", entry.fingerprint},
                        {"message", entry.message}});
  }
  const nlohmann::json document{
      {"about", "rung lint baseline: findings that are not reported; 'rung lint --write-baseline' rewrites it"},
      {"version", kVersion},
      {"findings", std::move(findings)}};
  return document.dump(2) + "\n";
}

std::optional<std::vector<BaselineEntry>> parse_baseline(std::string_view json, std::string* error) {
  auto fail = [&](std::string message) -> std::optional<std::vector<BaselineEntry>> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
  if (document.is_discarded() || !document.is_object()) return fail("not a JSON object");
  if (document.value("version", 0) != kVersion) return fail(fmt::format("\"version\" must be {}", kVersion));
  const auto findings = document.find("findings");
  if (findings == document.end() || !findings->is_array()) return fail("no \"findings\" list");
  std::vector<BaselineEntry> entries;
  for (const nlohmann::json& item : *findings) {
    auto text = [&](const char* key) -> std::optional<std::string> {
      const auto found = item.find(key);
      if (found == item.end()) return std::string();
      if (!found->is_string()) return std::nullopt;
      return found->get<std::string>();
    };
    if (!item.is_object()) return fail("a finding is not an object");
    std::optional<std::string> path = text("path"), code = text("code"), pou = text("pou"),
                               fingerprint = text("fingerprint"), message = text("message");
    if (!path || !code || !pou || !fingerprint || !message || path->empty() || code->empty() || fingerprint->empty()) {
      return fail("a finding needs \"path\", \"code\" and \"fingerprint\" strings");
    }
    entries.push_back(
        {std::move(*path), std::move(*code), std::move(*pou), std::move(*fingerprint), std::move(*message)});
  }
  return entries;
}

BaselineResult apply_baseline(const std::vector<BaselineEntry>& baseline, const check::Workspace& workspace,
                              std::vector<FileFindings>& files, const std::filesystem::path& root) {
  std::map<Key, size_t> remaining;
  for (const BaselineEntry& entry : baseline) ++remaining[key_of(entry)];
  BaselineResult result;
  std::set<std::string> linted;
  for (FileFindings& file : files) {
    linted.insert(baseline_path(file.path, root));
    std::erase_if(file.findings, [&](const Finding& finding) {
      auto found = remaining.find(key_of(baseline_entry(workspace, file, finding, root)));
      if (found == remaining.end() || found->second == 0) return false;
      --found->second;
      ++result.matched;
      return true;
    });
  }
  for (const auto& [key, count] : remaining) {
    if (linted.count(std::get<0>(key))) result.unmatched += count;
  }
  return result;
}

}  // namespace rung::lint
