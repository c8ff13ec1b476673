// Hover, signature help and inlay hints: what the code under or around the cursor is. Hover
// shows a declaration (hover_markdown.cpp) or the type of an expression; signature help the
// parameters of the call around the cursor; inlay hints the parameter names of informal
// arguments and implicit conversions. The answers come from checker/query (definition,
// type_at, call_site, declaration_text, inlay_hints).
#include <fmt/format.h>

#include "checker/query/call_site.hpp"
#include "checker/query/declaration_text.hpp"
#include "checker/query/definition.hpp"
#include "checker/query/doc_comment.hpp"
#include "checker/query/inlay_hints.hpp"
#include "checker/query/location.hpp"
#include "checker/query/position.hpp"
#include "checker/query/type_at.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/hover_markdown.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"
#include "parser/source/utf8.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;
using check::Symbol;

// LSP InlayHintKind.
constexpr int kHintType = 1;
constexpr int kHintParameter = 2;

Json markdown(std::string text) { return Json{{"kind", "markdown"}, {"value", std::move(text)}}; }

Json hover(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  if (document.project->removed.contains(document.source)) return nullptr;
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  const check::Workspace& workspace = document.workspace();
  const std::optional<query::QueryPoint> point = query::query_point(workspace, document.source, offset);
  if (!point) return nullptr;
  if (const Symbol* symbol = query::symbol_at(workspace, document.source, offset)) {
    Json result{{"contents", markdown(symbol_markdown(document.model(), *symbol))}};
    if (point->name) {
      result["range"] = session.range_of(
          document, query::location_in_file(document.model(), document.source, point->name.range()).range);
    }
    return result;
  }
  // A literal, an operator's expression, a name rung knows no declaration of (a builtin).
  const check::Type* type = query::type_at(workspace, document.source, offset);
  if (!type || type->is_unknown() || type->kind == check::TypeKind::Void) return nullptr;
  return Json{{"contents", markdown(fmt::format("type `{}`", type->name))}};
}

// UTF-16 length of `text` (signature labels count their parameters' offsets in UTF-16 units).
uint32_t utf16_size(std::string_view text) {
  uint32_t units = 0;
  for (size_t at = 0; at < text.size();) {
    const source::Utf8Step step = source::decode_utf8_at(text, at);
    units += source::utf16_length(step.code_point);
    at += step.length;
  }
  return units;
}

Json signature_help(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  if (document.project->removed.contains(document.source)) return nullptr;
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  const std::optional<query::CallSite> site = query::call_site_at(document.workspace(), document.source, offset);
  if (!site) return nullptr;
  const check::ProjectModel& model = document.model();
  const query::Signature signature = query::signature_of(model, *site->callee);
  const bool offsets = json_at(session.client_capabilities(), {"textDocument", "signatureHelp", "signatureInformation",
                                                               "parameterInformation", "labelOffsetSupport"}) == Json(true);
  Json parameters = Json::array();
  // No parameter matches the argument at the cursor (an unknown name, one argument too many):
  // an index past the last parameter, which VS Code and Neovim show as no highlight (LSP 3.17 has
  // no null here; 0 would wrongly mark the first parameter).
  size_t active = signature.parameters.size();
  for (size_t i = 0; i < signature.parameters.size(); ++i) {
    const Symbol& parameter = *signature.parameters[i];
    if (&parameter == site->active) active = i;
    const auto [begin, end] = signature.ranges[i];
    const std::string_view label = std::string_view(signature.label).substr(begin, end - begin);
    Json information{{"label", offsets ? Json::array({utf16_size(signature.label.substr(0, begin)),
                                                      utf16_size(signature.label.substr(0, end))})
                                       : Json(std::string(label))}};
    std::string doc(ast::var_section_name(parameter.section));
    if (parameter.has(check::kExtensible)) doc += " (extensible: more arguments may follow)";
    if (const std::string comment = query::doc_comment(model, parameter); !comment.empty()) doc += "\n\n" + comment;
    information["documentation"] = markdown(doc);
    parameters.push_back(std::move(information));
  }
  Json information{{"label", signature.label}, {"parameters", parameters}};
  std::string doc = symbol_role(model, *site->callee);
  if (const std::string comment = query::doc_comment(model, *site->callee); !comment.empty()) doc += "\n\n" + comment;
  information["documentation"] = markdown(doc);
  information["activeParameter"] = active;
  return Json{{"signatures", Json::array({information})}, {"activeSignature", 0}, {"activeParameter", active}};
}

Json inlay_hints(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  if (document.project->removed.contains(document.source)) return Json::array();
  const uint32_t begin = session.offset_of(document, json_at(params, {"range", "start"}));
  const uint32_t end = session.offset_of(document, json_at(params, {"range", "end"}));
  const TextRange range{begin, std::max(begin, end)};
  const auto names = query::parameter_hints(document.workspace(), document.source, range);
  const auto conversions = query::conversion_hints(document.workspace(), document.source, range);
  Json hints = Json::array();
  size_t n = 0, c = 0;
  // In text order; at one offset the parameter's name comes before the conversion of its value.
  while (n < names.size() || c < conversions.size()) {
    if (session.cancelled()) break;
    if (n < names.size() && (c == conversions.size() || names[n].offset <= conversions[c].offset)) {
      hints.push_back(Json{{"position", session.position_of(document, names[n].offset)},
                           {"label", fmt::format("{}:", names[n].parameter->name)},
                           {"kind", kHintParameter},
                           {"paddingRight", true}});
      ++n;
    } else {
      const query::ConversionHint& hint = conversions[c++];
      hints.push_back(Json{{"position", session.position_of(document, hint.offset)},
                           {"label", fmt::format("{}_TO_{}", hint.from->name, hint.to->name)},
                           {"kind", kHintType},
                           {"paddingRight", true},
                           {"tooltip", fmt::format("implicit conversion from {} to {}", hint.from->name, hint.to->name)}});
    }
  }
  return hints;
}

}  // namespace

void register_hover(Router& router) {
  router.capabilities()["hoverProvider"] = true;
  router.capabilities()["signatureHelpProvider"] =
      Json{{"triggerCharacters", Json::array({"(", ","})}, {"retriggerCharacters", Json::array({","})}};
  router.capabilities()["inlayHintProvider"] = true;
  router.on_request("textDocument/hover", hover);
  router.on_request("textDocument/signatureHelp", signature_help);
  router.on_request("textDocument/inlayHint", inlay_hints);
}

}  // namespace rung::lsp
