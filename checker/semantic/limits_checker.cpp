#include "checker/semantic/limits_checker.hpp"

#include <fmt/format.h>

#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

// Symbols whose declaration is a scope for the constants an array bound may name.
bool is_scope(SymbolKind kind) {
  return is_pou_kind(kind) || kind == SymbolKind::DataType || kind == SymbolKind::GlobalList;
}

std::string_view profile_label(const Profile& profile) {
  return profile.id == project::Profile::Openpcs ? "OpenPCS" : "this profile";
}

class LimitsChecker {
 public:
  LimitsChecker(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out)
      : model_(model), profile_(model.profile()), source_(model.source(source)), out_(out) {}

  void run() {
    const bool any_limit = profile_.max_identifier_length != 0 || profile_.max_array_dimensions != 0 ||
                           profile_.max_names_per_declaration != 0 || profile_.array_bound_limit != 0 ||
                           !profile_.nested_calls;
    if (!any_limit || source_.library || !source_.document->tree()) return;
    for (const Symbol& symbol : source_.symbols.storage) {
      check_identifier(symbol);
      if (is_scope(symbol.kind) && symbol.node) scopes_.push_back(&symbol);
    }
    walk_preorder(source_.document->tree()->root(), [&](SyntaxNode node) {
      const std::string_view kind = node.kind();
      if (kind == "var_declaration") check_name_count(node);
      if (kind == "array_type") check_array(node);
      if (kind == "call_expression") check_nested_call(node);
      return true;
    });
  }

 private:
  void report(std::string message, TextRange range, std::string help) {
    out_.push_back(make_diagnostic(codes::kImplementationLimit, std::move(message), range, std::move(help)));
  }

  // OpenPCS S1028: only the first 64 characters of a name count, longer names are refused.
  void check_identifier(const Symbol& symbol) {
    const uint32_t limit = profile_.max_identifier_length;
    if (limit == 0 || symbol.name.size() <= limit || symbol.name_range.end <= symbol.name_range.begin) return;
    report(fmt::format("'{}' has {} characters; {} allows identifiers of at most {}", symbol.name, symbol.name.size(),
                       profile_label(profile_), limit),
           symbol.name_range, fmt::format("shorten the name to {} characters or fewer", limit));
  }

  // OpenPCS S4001: `a, b, c : INT;` lists at most 60 names.
  void check_name_count(SyntaxNode declaration) {
    const uint32_t limit = profile_.max_names_per_declaration;
    if (limit == 0) return;
    const std::vector<SyntaxNode> names = declaration.children_by_field("name");
    if (names.size() <= limit) return;
    report(
        fmt::format("{} names in one declaration; {} allows at most {}", names.size(), profile_label(profile_), limit),
        {names[limit].begin(), names.back().end()}, "split the list into several declarations");
  }

  void check_array(SyntaxNode array) {
    const std::vector<SyntaxNode> ranges = array.children_of_kind("range");
    const uint32_t dimensions = static_cast<uint32_t>(ranges.size() + array.children_of_kind("wildcard").size());
    if (profile_.max_array_dimensions != 0 && dimensions > profile_.max_array_dimensions) {
      report(fmt::format("an array with {} subscripts; {} allows at most {}", dimensions, profile_label(profile_),
                         profile_.max_array_dimensions),
             {array.begin(), array.child_by_field("element") ? array.child_by_field("element").begin() : array.end()},
             "use an array of arrays or a structure");
    }
    if (profile_.array_bound_limit == 0) return;
    const Symbol* scope = scope_of(array);
    for (const SyntaxNode& range : ranges) {
      for (const char* field : {"lower", "upper"}) check_bound(range.child_by_field(field), field, scope);
    }
  }

  // OpenPCS C10076/C10077: array indexes are 16-bit, -32767..32767.
  void check_bound(SyntaxNode bound, std::string_view which, const Symbol* scope) {
    if (!bound) return;
    const std::optional<ConstValue> value = model_.constant_value(bound, scope);
    if (!value || !value->is_integer()) return;
    const __int128 limit = profile_.array_bound_limit;
    if (value->integer >= -limit && value->integer <= limit) return;
    report(fmt::format("the {} array bound {} is outside -{}..{}, the index range of {}", which,
                       int128_to_string(value->integer), profile_.array_bound_limit, profile_.array_bound_limit,
                       profile_label(profile_)),
           bound.range(), "use bounds inside the range, or several smaller arrays");
  }

  // OpenPCS C10110 ("nested functions not supported"): MAX(ABS(b), 3) needs ABS(b) in a variable
  // first. Only the outermost nested call is reported: moving it out moves the calls inside it too.
  void check_nested_call(SyntaxNode call) {
    if (profile_.nested_calls) return;
    int levels = 0;
    SyntaxNode outer;
    for (SyntaxNode node = call.parent(); node; node = node.parent()) {
      const std::string_view kind = node.kind();
      if (kind == "argument" || kind == "output_argument") {
        SyntaxNode list = node.parent();
        SyntaxNode owner = list ? list.parent() : SyntaxNode();
        if (owner && owner.kind() == "call_expression") {
          ++levels;
          outer = owner;
          node = owner;
        }
      }
      if (kind.ends_with("_statement") || kind == "statement_list" || kind.ends_with("_declaration")) break;
    }
    if (levels != 1) return;
    SyntaxNode function = outer.child_by_field("function");
    report(fmt::format("a call as an argument of '{}': {} does not compile nested calls",
                       function ? function.text() : std::string_view("a call"), profile_label(profile_)),
           call.range(), "assign the inner call's result to a variable and pass that");
  }

  // The innermost POU, type or global list whose declaration contains `node`.
  const Symbol* scope_of(SyntaxNode node) const {
    const Symbol* best = nullptr;
    for (const Symbol* scope : scopes_) {
      const TextRange range = scope->node.range();
      if (range.begin > node.begin() || range.end < node.end()) continue;
      if (!best || range.end - range.begin < best->node.range().end - best->node.range().begin) best = scope;
    }
    return best;
  }

  const ProjectModel& model_;
  const Profile& profile_;
  const Source& source_;
  std::vector<Diagnostic>& out_;
  std::vector<const Symbol*> scopes_;
};

}  // namespace

void check_limits(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  LimitsChecker(model, source, out).run();
}

}  // namespace rung::check
