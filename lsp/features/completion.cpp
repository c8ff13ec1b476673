// Completion: textDocument/completion and completionItem/resolve. What fits at the cursor is
// checker/query/completion's answer; this file gives each candidate its LSP shape — label, kind,
// the text inserted (keywords in the project's [format] keyword_case, skeletons as snippets when
// the client takes them), the order — and resolve adds the declaration and its doc comment.
#include <fmt/format.h>

#include "checker/query/completion.hpp"
#include "checker/query/declaration_text.hpp"
#include "checker/query/resolve.hpp"
#include "lsp/features/completion_snippets.hpp"
#include "lsp/features/features.hpp"
#include "lsp/features/hover_markdown.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {
namespace {

namespace query = check::query;
using check::Symbol;
using check::SymbolKind;

// LSP CompletionItemKind.
enum ItemKind : int {
  kMethod = 2,
  kFunction = 3,
  kField = 5,
  kVariable = 6,
  kClass = 7,
  kInterface = 8,
  kModule = 9,
  kProperty = 10,
  kEnum = 13,
  kKeyword = 14,
  kSnippet = 15,
  kEnumMember = 20,
  kConstant = 21,
  kStruct = 22,
};
constexpr int kPlainText = 1;
constexpr int kSnippetFormat = 2;

int item_kind(const check::ProjectModel& model, const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::Variable:
      if (symbol.has(check::kConstant)) return kConstant;
      return symbol.owner && symbol.owner->kind == SymbolKind::DataType ? kField : kVariable;
    case SymbolKind::EnumValue: return kEnumMember;
    case SymbolKind::Function: return kFunction;
    case SymbolKind::Method:
    case SymbolKind::Action: return kMethod;
    case SymbolKind::Property: return kProperty;
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class: return kClass;
    case SymbolKind::Interface: return kInterface;
    case SymbolKind::Program:
    case SymbolKind::GlobalList:
    case SymbolKind::Namespace: return kModule;
    case SymbolKind::DataType: {
      const check::TypeKind type = check::underlying(model.type_of(&symbol))->kind;
      if (type == check::TypeKind::Enum) return kEnum;
      return type == check::TypeKind::Struct || type == check::TypeKind::Union ? kStruct : kClass;
    }
    default: return kVariable;
  }
}

// One line next to the label: a variable's type, a callable's signature, a type's kind.
std::string item_detail(const check::ProjectModel& model, const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::Variable: return query::written_type(model, symbol);
    case SymbolKind::EnumValue: return symbol.owner ? std::string(symbol.owner->name) : std::string();
    case SymbolKind::Function:
    case SymbolKind::Method:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class:
    case SymbolKind::Program:
    case SymbolKind::Action: return query::signature_of(model, symbol).label;
    default: return symbol_role(model, symbol);
  }
}

bool snippet_support(const Session& session) {
  return json_at(session.client_capabilities(), {"textDocument", "completion", "completionItem", "snippetSupport"}) ==
         Json(true);
}

// What resolve needs to find the declaration again: where its name is declared.
Json symbol_data(const DocumentRef& document, const Symbol& symbol) {
  return Json{{"uri", document.uri},
              {"name", std::string(symbol.name)},
              {"source", symbol.source},
              {"begin", symbol.name_range.begin},
              {"end", symbol.name_range.end}};
}

Json completion(Session& session, const Json& params) {
  const DocumentRef document = session.document(params);
  Json result{{"isIncomplete", false}, {"items", Json::array()}};
  if (document.project->removed.contains(document.source)) return result;
  const uint32_t offset = session.offset_of(document, json_at(params, {"position"}));
  const query::Completion found = query::complete_at(document.workspace(), document.source, offset);
  const check::ProjectModel& model = document.model();
  const project::FormatSettings& format = document.settings().format;
  const bool snippets = snippet_support(session);
  const Json range = session.range_of(document, {found.word.begin, offset});
  Json& items = result["items"];
  for (size_t i = 0; i < found.candidates.size(); ++i) {
    const query::CompletionCandidate& candidate = found.candidates[i];
    Json item{{"sortText", fmt::format("{:05}", i)}};
    std::string text;
    switch (candidate.kind) {
      case query::CandidateKind::Symbol: {
        const Symbol& symbol = *candidate.symbol;
        text = candidate.qualifier.empty() ? std::string(symbol.name)
                                           : fmt::format("{}.{}", candidate.qualifier, symbol.name);
        item["label"] = text;
        item["kind"] = item_kind(model, symbol);
        item["detail"] = item_detail(model, symbol);
        item["data"] = symbol_data(document, symbol);
        if (symbol.has(check::kObsolete)) item["tags"] = Json::array({1});  // Deprecated
        break;
      }
      case query::CandidateKind::Parameter: {
        const Symbol& parameter = *candidate.symbol;
        const bool output = parameter.section == ast::VarSection::Output;
        item["label"] = fmt::format("{} {}", parameter.name, output ? "=>" : ":=");
        item["filterText"] = std::string(parameter.name);
        item["kind"] = kField;
        item["detail"] = fmt::format("{} : {}", ast::var_section_name(parameter.section), query::written_type(model, parameter));
        item["data"] = symbol_data(document, parameter);
        text = fmt::format("{} {} ", parameter.name, output ? "=>" : ":=");
        break;
      }
      case query::CandidateKind::Keyword:
      case query::CandidateKind::ElementaryType: {
        const bool type = candidate.kind == query::CandidateKind::ElementaryType;
        text = keyword_in_case(candidate.word, format, found.prefix, type);
        item["label"] = text;
        item["kind"] = kKeyword;
        if (type) item["detail"] = "elementary type";
        break;
      }
      case query::CandidateKind::LibraryNamespace:
        text = std::string(candidate.word);
        item["label"] = text;
        item["kind"] = kModule;
        item["detail"] = "library";
        break;
      case query::CandidateKind::Snippet: {
        const Snippet skeleton = snippet(candidate.word, format, found.prefix, snippets);
        if (skeleton.text.empty()) continue;
        text = skeleton.text;
        item["label"] = skeleton.label;
        item["filterText"] = std::string(candidate.word);
        item["kind"] = kSnippet;
        item["detail"] = skeleton.detail;
        item["insertTextFormat"] = snippets ? kSnippetFormat : kPlainText;
        break;
      }
    }
    item["textEdit"] = Json{{"range", range}, {"newText", text}};
    items.push_back(std::move(item));
  }
  result["isIncomplete"] = found.incomplete;
  return result;
}

// The declaration a completion item stands for, found again from its data.
const Symbol* symbol_of_item(Session& session, const Json& item) {
  const Json& data = json_at(item, {"data"});
  const std::string uri = json_string(data, "uri");
  if (uri.empty() || !data.contains("source") || !data["source"].is_number_unsigned() || !data.contains("begin") ||
      !data["begin"].is_number_unsigned() || !data.contains("end") || !data["end"].is_number_unsigned()) {
    return nullptr;
  }
  const auto document = session.find_document(uri);
  if (!document) return nullptr;
  const check::ProjectModel& model = document->model();
  const uint64_t source = data["source"].get<uint64_t>();
  if (source >= model.source_count()) return nullptr;
  const Symbol* symbol = query::symbol_declared_at(model, static_cast<check::SourceId>(source),
                                                   TextRange{static_cast<uint32_t>(data["begin"].get<uint64_t>()),
                                                             static_cast<uint32_t>(data["end"].get<uint64_t>())});
  // After an edit the same place may declare something else.
  return symbol && check::names_equal(symbol->name, json_string(data, "name")) ? symbol : nullptr;
}

Json resolve(Session& session, const Json& params) {
  Json item = params;
  if (!item.is_object()) throw RpcError{ErrorCode::InvalidParams, "a CompletionItem is expected"};
  const Symbol* symbol = symbol_of_item(session, item);
  if (!symbol) return item;
  const auto document = session.find_document(json_string(item["data"], "uri"));
  item["documentation"] = Json{{"kind", "markdown"}, {"value", symbol_markdown(document->model(), *symbol)}};
  return item;
}

}  // namespace

void register_completion(Router& router) {
  router.capabilities()["completionProvider"] = Json{{"triggerCharacters", Json::array({".", "#", "("})},
                                                     {"resolveProvider", true}};
  router.on_request("textDocument/completion", completion);
  router.on_request("completionItem/resolve", resolve);
}

}  // namespace rung::lsp
