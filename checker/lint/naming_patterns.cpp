#include "checker/lint/naming_patterns.hpp"

namespace rung::lint::naming {
namespace {

bool is_alnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}
bool is_upper_or_digit(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Whether the name goes on as a new word at `at`, right after `prefix`.
bool new_word_at(std::string_view name, size_t at, std::string_view prefix) {
  if (at >= name.size()) return false;
  if (!is_alnum(prefix.back())) return true;
  return is_upper_or_digit(name[at]) || name[at] == '_';
}

bool chain_matches(std::string_view name, size_t at, std::span<const std::string> chain, size_t level) {
  for (std::string_view prefix : alternatives(chain[level])) {
    if (name.substr(at, prefix.size()) != prefix) continue;
    const size_t next = at + prefix.size();
    if (new_word_at(name, next, prefix)) return true;
    if (level + 1 < chain.size() && chain_matches(name, next, chain, level + 1)) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string_view> alternatives(std::string_view pattern) {
  std::vector<std::string_view> out;
  while (true) {
    const size_t bar = pattern.find('|');
    const std::string_view one = trimmed(pattern.substr(0, bar));
    if (!one.empty()) out.push_back(one);
    if (bar == std::string_view::npos) break;
    pattern.remove_prefix(bar + 1);
  }
  return out;
}

bool has_prefix(std::string_view name, std::string_view pattern) {
  const std::string chain[] = {std::string(pattern)};
  return has_prefix_chain(name, chain);
}

bool has_prefix_chain(std::string_view name, std::span<const std::string> chain) {
  if (chain.empty() || alternatives(chain.front()).empty()) return true;
  size_t levels = 0;  // the chain ends at its first empty level
  while (levels < chain.size() && !alternatives(chain[levels]).empty()) ++levels;
  return chain_matches(name, 0, chain.first(levels), 0);
}

size_t matched_prefix_length(std::string_view name, std::string_view pattern) {
  size_t best = 0;
  for (std::string_view prefix : alternatives(pattern)) {
    if (prefix.size() > best && name.substr(0, prefix.size()) == prefix && new_word_at(name, prefix.size(), prefix)) {
      best = prefix.size();
    }
  }
  return best;
}

std::string suggested_name(std::string_view name, std::string_view pattern) {
  const std::vector<std::string_view> options = alternatives(pattern);
  if (options.empty()) return std::string(name);
  const std::string_view prefix = options.front();
  std::string rest(name);
  if (is_alnum(prefix.back()) && !rest.empty() && rest[0] >= 'a' && rest[0] <= 'z') {
    rest[0] = static_cast<char>(rest[0] - 'a' + 'A');
  }
  return std::string(prefix) + rest;
}

std::string describe_pattern(std::string_view pattern) {
  const std::vector<std::string_view> options = alternatives(pattern);
  std::string text = options.size() > 1 ? "one of " : "";
  for (size_t i = 0; i < options.size(); ++i) {
    if (i > 0) text += ", ";
    text += "'" + std::string(options[i]) + "'";
  }
  return text;
}

}  // namespace rung::lint::naming
