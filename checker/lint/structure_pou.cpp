#include "checker/lint/structure_pou.hpp"

namespace rung::lint {
namespace {

bool is_body_kind(std::string_view kind) {
  return kind == "statement_list" || kind == "il_body" || kind == "sfc_network";
}

}  // namespace

std::string_view pou_kind_label(const check::Symbol& pou) {
  switch (pou.kind) {
    case check::SymbolKind::Program: return "program";
    case check::SymbolKind::Function: return "function";
    case check::SymbolKind::FunctionBlock: return "function block";
    case check::SymbolKind::Class: return "class";
    case check::SymbolKind::Interface: return "interface";
    case check::SymbolKind::Method: return pou.node.kind() == "property_accessor" ? "property accessor" : "method";
    case check::SymbolKind::Property: return "property";
    case check::SymbolKind::Action: return "action";
    case check::SymbolKind::Transition: return "transition";
    default: return "POU";
  }
}

std::vector<SyntaxNode> bodies_of(const check::Symbol& pou) {
  std::vector<SyntaxNode> bodies;
  if (!pou.node) return bodies;
  if (pou.node.kind() == "source_file") {
    for (SyntaxNode child : pou.node.named_children()) {
      if (is_body_kind(child.kind())) bodies.push_back(child);
    }
    return bodies;
  }
  for (SyntaxNode body : pou.node.children_by_field("body")) {
    if (is_body_kind(body.kind())) bodies.push_back(body);
  }
  return bodies;
}

std::string pou_label(const check::Symbol& pou) {
  std::string name(pou.name);
  if (pou.owner && !pou.owner->name.empty() && check::is_pou_kind(pou.owner->kind)) {
    name = std::string(pou.owner->name) + "." + name;
  }
  if (pou.name.empty()) return "the program";  // a snippet without POU header
  return std::string(pou_kind_label(pou)) + " '" + name + "'";
}

bool signature_is_given(const check::ProjectModel& model, const check::Symbol& pou) {
  if (pou.kind != check::SymbolKind::Method && pou.kind != check::SymbolKind::Property) return false;
  if (pou.node && pou.node.kind() == "property_accessor") return true;  // GET/SET of its property
  for (std::string_view runtime : {"FB_init", "FB_reinit", "FB_exit"}) {
    if (check::names_equal(pou.name, runtime)) return true;
  }
  if (pou.has(check::kOverride)) return true;
  const check::Symbol* owner = pou.owner;
  if (!owner) return false;
  if (owner->base && model.find_member(owner->base, pou.name)) return true;
  for (const check::Symbol* interface : owner->interfaces) {
    if (model.find_member(interface, pou.name)) return true;
  }
  // An interface that extends others repeats their members' signatures.
  if (owner->kind == check::SymbolKind::Interface) {
    for (const check::Symbol* base : owner->bases) {
      if (base && model.find_member(base, pou.name)) return true;
    }
  }
  return false;
}

std::string message_excerpt(std::string_view text, size_t limit) {
  text = text.substr(0, text.find_first_of("\r\n"));
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  if (text.size() <= limit) return std::string(text);
  size_t cut = limit > 3 ? limit - 3 : 0;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // a continuation byte
  return std::string(text.substr(0, cut)) + "...";
}

}  // namespace rung::lint
