#include "checker/query/symbol_search.hpp"

#include <algorithm>

namespace rung::check::query {
namespace {

constexpr int kExact = 10000;
constexpr int kPrefix = 8000;
constexpr int kPart = 6000;
constexpr int kScattered = 2000;
constexpr int kWordStartBonus = 20;
constexpr int kMostScattered = kPart - 1000;  // below every part of a name

// The name, a start of it or a part of it, rather than letters spread over it.
bool is_close(const SymbolMatch& match) {
  return match.score > kMostScattered;
}

bool is_lower(char c) {
  return c >= 'a' && c <= 'z';
}
bool is_upper(char c) {
  return c >= 'A' && c <= 'Z';
}

bool is_word_start(std::string_view text, size_t at) {
  if (at == 0) return true;
  const char before = text[at - 1];
  return before == '_' || before == '.' || (is_lower(before) && is_upper(text[at]));
}

class Collector {
 public:
  Collector(std::string_view query, std::vector<SymbolMatch>& out) : query_(query), out_(out) {}

  void add_source(const Source& source) {
    for (const Symbol* top : source.symbols.top_level) add_top_level(*top);
  }

 private:
  void add_top_level(const Symbol& symbol) {
    if (symbol.kind == SymbolKind::GlobalList) {
      // A PROGRAM's VAR_GLOBAL list carries the program's name: only its variables are new.
      if (!symbol.owner) add(symbol, {});
      for (const Symbol* variable : symbol.ordered) add(*variable, symbol.name);
      return;
    }
    add(symbol, {});
    for (const Symbol* member : symbol.ordered) {
      // Methods, properties, actions, transitions, enum values (a property's GET and SET are
      // members of the property, one level further down, and not listed).
      if (member->kind == SymbolKind::EnumValue || is_pou_kind(member->kind)) add(*member, symbol.name);
    }
  }

  // `container` non-empty: a member; methods, properties, actions and enum values are shown (and
  // written in code) with it, global variables without.
  void add(const Symbol& symbol, std::string_view container) {
    if (symbol.name.empty() || symbol.has(kHide)) return;
    const bool qualified = !container.empty() && symbol.kind != SymbolKind::Variable;
    std::optional<int> score = match_score(query_, symbol.name);
    std::string shown(symbol.name);
    if (qualified) {
      shown = std::string(container) + "." + shown;
      const std::optional<int> whole = match_score(query_, shown);
      if (whole && (!score || *whole > *score)) score = whole;
    }
    if (!score) return;
    out_.push_back({.symbol = &symbol,
                    .name = std::move(shown),
                    .container = std::string(container),
                    .score = *score,
                    .library = symbol.has(kLibrary)});
  }

  std::string_view query_;
  std::vector<SymbolMatch>& out_;
};

}  // namespace

std::optional<int> match_score(std::string_view query, std::string_view candidate) {
  if (query.empty()) return 0;
  if (query.size() > candidate.size()) return std::nullopt;
  if (names_equal(query, candidate)) return kExact;
  if (names_equal(candidate.substr(0, query.size()), query)) return kPrefix;
  for (size_t at = 1; at + query.size() <= candidate.size(); ++at) {
    if (names_equal(candidate.substr(at, query.size()), query)) {
      return kPart - static_cast<int>(std::min<size_t>(at, 500)) + (is_word_start(candidate, at) ? 500 : 0);
    }
  }
  int score = kScattered;
  size_t next = 0;  // the next query character to find
  size_t last = 0;  // where the previous one was found
  for (size_t at = 0; at < candidate.size() && next < query.size(); ++at) {
    if (ascii_upper(candidate[at]) != ascii_upper(query[next])) continue;
    if (is_word_start(candidate, at)) score += kWordStartBonus;
    if (next > 0) score -= static_cast<int>(std::min<size_t>(at - last - 1, 50));  // letters skipped
    last = at;
    ++next;
  }
  if (next < query.size()) return std::nullopt;
  return std::clamp(score, 1, kMostScattered);
}

bool better_match(const SymbolMatch& a, const SymbolMatch& b) {
  if (is_close(a) != is_close(b)) return is_close(a);
  if (a.library != b.library) return !a.library;
  if (a.score != b.score) return a.score > b.score;
  if (a.name.size() != b.name.size()) return a.name.size() < b.name.size();
  // Alphabetically, ignoring case (without upper-case copies: this runs for every comparison).
  for (size_t i = 0; i < a.name.size(); ++i) {
    const char upper_a = ascii_upper(a.name[i]);
    const char upper_b = ascii_upper(b.name[i]);
    if (upper_a != upper_b) return upper_a < upper_b;
  }
  if (a.symbol->source != b.symbol->source) return a.symbol->source < b.symbol->source;
  return a.symbol->name_range.begin < b.symbol->name_range.begin;
}

std::vector<SymbolMatch> search_symbols(const ProjectModel& model, std::string_view query,
                                        const SymbolSearch& options) {
  std::vector<SymbolMatch> matches;
  Collector collector(query, matches);
  for (SourceId id = 0; id < model.source_count(); ++id) {
    if (options.cancelled && options.cancelled()) break;
    if (options.skip && options.skip(id)) continue;
    collector.add_source(model.source(id));
  }
  const size_t kept = std::min(options.limit, matches.size());
  std::partial_sort(matches.begin(), matches.begin() + static_cast<std::ptrdiff_t>(kept), matches.end(), better_match);
  matches.resize(kept);
  return matches;
}

}  // namespace rung::check::query
