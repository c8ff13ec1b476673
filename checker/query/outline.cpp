#include "checker/query/outline.hpp"

#include <algorithm>

#include "checker/query/declaration_text.hpp"
#include "checker/query/location.hpp"

namespace rung::check::query {
namespace {

constexpr std::string_view kNoName = "(no name)";
constexpr size_t kDetailLimit = 80;

TextRange cover(TextRange a, TextRange b) {
  return {std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

void sort_by_position(std::vector<OutlineItem>& items) {
  std::stable_sort(items.begin(), items.end(), [](const OutlineItem& a, const OutlineItem& b) {
    return a.range.begin != b.range.begin ? a.range.begin < b.range.begin : a.selection.begin < b.selection.begin;
  });
}

// The value of the nearest Name="..." attribute before `file_offset` in a TwinCAT file when no
// element closes in between (the element whose code starts there) and it spells `name`.
std::optional<TextRange> twincat_element_name(const Document& document, uint32_t file_offset, std::string_view name) {
  const containers::ContainerDocument* container = document.container();
  if (!container || container->kind != containers::ContainerKind::TwinCat || name.empty()) return std::nullopt;
  const std::string_view text = document.file_text();
  constexpr std::string_view kAttribute = "Name=\"";
  const size_t attribute = text.rfind(kAttribute, std::min<size_t>(file_offset, text.size()));
  if (attribute == std::string_view::npos) return std::nullopt;
  const size_t value_begin = attribute + kAttribute.size();
  const size_t value_end = text.find('"', value_begin);
  if (value_end == std::string_view::npos || value_end > file_offset) return std::nullopt;
  if (text.substr(value_end, file_offset - value_end).find("</") != std::string_view::npos) return std::nullopt;
  if (!names_equal(text.substr(value_begin, value_end - value_begin), name)) return std::nullopt;
  return TextRange{static_cast<uint32_t>(value_begin), static_cast<uint32_t>(value_end)};
}

class OutlineBuilder {
 public:
  OutlineBuilder(const ProjectModel& model, SourceId source)
      : model_(model), source_(source), document_(*model.source(source).document) {}

  std::vector<OutlineItem> build() {
    std::vector<OutlineItem> items;
    for (const Symbol* top : model_.source(source_).symbols.top_level) add_top_level(*top, items);
    sort_by_position(items);
    return items;
  }

 private:
  void add_top_level(const Symbol& symbol, std::vector<OutlineItem>& items) {
    switch (symbol.kind) {
      case SymbolKind::DataType: items.push_back(type_item(symbol)); break;
      case SymbolKind::GlobalList:
        if (!symbol.owner) add_global_list(symbol, items);  // a PROGRAM's VAR_GLOBAL is shown in it
        break;
      case SymbolKind::Configuration: items.push_back(configuration_item(symbol.node)); break;
      default:
        if (!is_pou_kind(symbol.kind)) break;
        if (symbol.node && symbol.node.kind() == "source_file") {
          add_snippet(symbol.node, items);  // statements without a POU around them
        } else {
          items.push_back(pou_item(symbol));
        }
    }
  }

  // A declaration part as a detail: its code on one line, without comments, cut when long.
  std::string text_of(SyntaxNode node) const {
    return node ? cut_text(code_text(document_.tree()->root(), node.range()), kDetailLimit) : std::string();
  }

  TextRange file_range(TextRange tree_range) const {
    const uint32_t begin = document_.file_offset_of(tree_range.begin);
    return {begin, std::max(begin, document_.file_end_offset_of(tree_range.end))};
  }

  // An item for a declaration `node` named by the token `name` (null: `fallback_name`, selected
  // at `fallback_selection`).
  OutlineItem item(OutlineKind kind, SyntaxNode node, SyntaxNode name, std::string detail = {}) const {
    OutlineItem out;
    out.kind = kind;
    out.detail = std::move(detail);
    out.range = file_range(node.range());
    if (name && !name.text().empty()) {
      out.name = std::string(name.text());
      out.selection = file_range(name.range());
    } else {
      out.name = std::string(kNoName);
      out.selection = {out.range.begin, out.range.begin};
    }
    return out;
  }

  // Makes the item's range cover its name and children (a TwinCAT name in the XML, members
  // following their block in the object shape), children in text order.
  static void finish(OutlineItem& item) {
    sort_by_position(item.children);
    item.range = cover(item.range, item.selection);
    for (const OutlineItem& child : item.children) item.range = cover(item.range, child.range);
  }

  OutlineItem pou_item(const Symbol& pou) {
    OutlineItem out = item(outline_kind_of(pou), pou.node, SyntaxNode(), pou_detail(pou));
    out.name = pou.name.empty() ? std::string(kNoName) : std::string(pou.name);
    out.selection = name_range_in_file(model_, pou);
    for (SyntaxNode block : pou.node.children_of_kind("var_block")) out.children.push_back(block_item(block));
    for (const Symbol* member : pou.ordered) {
      if (member->kind == SymbolKind::DataType) out.children.push_back(type_item(*member));
      if (is_pou_kind(member->kind)) out.children.push_back(pou_item(*member));
    }
    if (SyntaxNode body = pou.node.child_by_field("body"); body && body.kind() == "sfc_network") {
      add_sfc(body, out.children);
    }
    finish(out);
    return out;
  }

  std::string pou_detail(const Symbol& pou) const {
    if (pou.type_node) return text_of(pou.type_node);
    std::string detail;
    auto list = [&detail](std::string_view keyword, const std::vector<SyntaxNode>& names) {
      if (names.empty()) return;
      if (!detail.empty()) detail += ' ';
      detail += keyword;
      for (size_t i = 0; i < names.size(); ++i) detail += (i == 0 ? " " : ", ") + std::string(names[i].text());
    };
    list("EXTENDS", pou.base_nodes);
    list("IMPLEMENTS", pou.interface_nodes);
    return cut_text(detail, kDetailLimit);
  }

  OutlineItem block_item(SyntaxNode block_node) const {
    const ast::VarBlock block(block_node);
    const ast::VarSection section = block.section();
    SyntaxNode keyword = block_node.child_by_field("kind");
    OutlineItem out = item(OutlineKind::VarBlock, block_node, SyntaxNode());
    out.name = section == ast::VarSection::Unknown && keyword ? std::string(keyword.text())
                                                              : std::string(ast::var_section_name(section));
    if (keyword) out.selection = file_range(keyword.range());
    for (SyntaxNode qualifier : block_node.children_of_kind("var_qualifier")) {
      out.detail += (out.detail.empty() ? "" : " ") + upper_name(qualifier.text());
    }
    const OutlineKind variable = block.has_qualifier("CONSTANT") ? OutlineKind::Constant : OutlineKind::Variable;
    for (const ast::VarDeclaration& declaration : block.declarations())
      add_variables(declaration, variable, out.children);
    finish(out);
    return out;
  }

  void add_variables(const ast::VarDeclaration& declaration, OutlineKind kind, std::vector<OutlineItem>& out) const {
    const ast::VarDeclaration::Parts parts = declaration.parts();
    const std::string type = text_of(parts.type);
    for (SyntaxNode name : parts.names) out.push_back(item(kind, declaration.node(), name, type));
  }

  OutlineItem type_item(const Symbol& type) {
    SyntaxNode node = type.node;
    // TYPE T : ... END_TYPE holding one declaration: the whole block is that type's.
    SyntaxNode holder = node.parent();
    const bool whole_block = holder && holder.kind() == "type_declaration" && holder.named_children().size() == 1;
    OutlineItem out = item(outline_kind_of(type), whole_block ? holder : node, SyntaxNode());
    out.name = type.name.empty() ? std::string(kNoName) : std::string(type.name);
    out.selection = name_range_in_file(model_, type);
    if (const SyntaxNode base = node.child_by_field("base")) {
      out.detail = text_of(base);  // an enum's base type
    } else if (type.type_node) {
      out.detail = text_of(type.type_node);  // an alias
    } else if (!type.base_nodes.empty()) {
      out.detail = "EXTENDS " + text_of(type.base_nodes.front());
    }
    for (const ast::VarDeclaration& field : ast::TypeDeclaration(node, ast::TypeKind::Struct).fields()) {
      add_variables(field, OutlineKind::Field, out.children);
    }
    for (SyntaxNode value : node.children_of_kind("enum_value")) {
      SyntaxNode written = value.child_by_field("value");
      out.children.push_back(item(OutlineKind::EnumValue, value, value.child_by_field("name"), text_of(written)));
    }
    finish(out);
    return out;
  }

  // A global variable list with its VAR_GLOBAL blocks (several blocks of one file form one list);
  // blocks inside a CONFIGURATION are shown there.
  void add_global_list(const Symbol& list, std::vector<OutlineItem>& items) {
    std::vector<SyntaxNode> blocks{list.node};
    for (const Symbol* variable : list.ordered) {
      SyntaxNode block = variable->node ? variable->node.parent() : SyntaxNode();
      if (block && block.kind() == "var_block" &&
          std::none_of(blocks.begin(), blocks.end(), [&](SyntaxNode known) { return known == block; })) {
        blocks.push_back(block);
      }
    }
    std::erase_if(blocks, [](SyntaxNode block) { return !block || inside_configuration(block); });
    if (blocks.empty()) return;
    OutlineItem out = item(OutlineKind::GlobalList, blocks.front(), SyntaxNode());
    out.name = list.name.empty() ? std::string(kNoName) : std::string(list.name);
    for (SyntaxNode block : blocks) out.children.push_back(block_item(block));
    sort_by_position(out.children);
    out.selection = name_range_in_file(model_, list);
    if (out.selection.begin == out.selection.end) out.selection = out.children.front().selection;  // VAR_GLOBAL
    finish(out);
    items.push_back(std::move(out));
  }

  static bool inside_configuration(SyntaxNode node) {
    for (SyntaxNode at = node.parent(); at; at = at.parent()) {
      if (at.kind() == "configuration_declaration" || at.kind() == "resource_declaration") return true;
    }
    return false;
  }

  OutlineItem configuration_item(SyntaxNode node) const {
    const bool resource = node.kind() == "resource_declaration";
    SyntaxNode processor = node.child_by_field("processor");
    OutlineItem out = item(resource ? OutlineKind::Resource : OutlineKind::Configuration, node,
                           node.child_by_field("name"), processor ? "ON " + text_of(processor) : "");
    for (SyntaxNode child : node.named_children()) {
      const std::string_view kind = child.kind();
      if (kind == "var_block") {
        out.children.push_back(block_item(child));
      } else if (kind == "resource_declaration") {
        out.children.push_back(configuration_item(child));
      } else if (kind == "task_configuration") {
        SyntaxNode arguments = child.child_by_field("arguments");
        out.children.push_back(item(OutlineKind::Task, child, child.child_by_field("name"), text_of(arguments)));
      } else if (kind == "program_configuration") {
        SyntaxNode task = child.child_by_field("task");
        SyntaxNode type = child.child_by_field("type");
        std::string detail;
        if (task) detail.append("WITH ").append(task.text()).append(" : ");
        detail += text_of(type);
        out.children.push_back(item(OutlineKind::ProgramInstance, child, child.child_by_field("name"), detail));
      }
    }
    finish(out);
    return out;
  }

  // Steps and transitions of a textual SFC network (its ACTION blocks are the POU's actions).
  void add_sfc(SyntaxNode network, std::vector<OutlineItem>& out) const {
    for (SyntaxNode child : network.named_children()) {
      if (child.kind() == "sfc_step") {
        const bool initial = child.child(0) && child.child(0).kind() == "INITIAL_STEP";
        out.push_back(item(OutlineKind::Step, child, child.child_by_field("name"), initial ? "INITIAL_STEP" : ""));
      } else if (child.kind() == "sfc_transition") {
        out.push_back(transition_item(child));
      }
    }
  }

  OutlineItem transition_item(SyntaxNode transition) const {
    auto steps = [&](std::string_view field) {
      std::string text;
      for (SyntaxNode step : transition.children_by_field(field)) {
        if (step.kind() == "identifier") text += (text.empty() ? "" : ", ") + std::string(step.text());  // not ( , )
      }
      return text;
    };
    const std::string from_to = steps("from") + " -> " + steps("to");
    SyntaxNode name = transition.child_by_field("name");
    SyntaxNode condition = transition.child_by_field("condition");
    OutlineItem out = item(OutlineKind::Transition, transition, name, text_of(condition));
    if (!name) {
      out.name = from_to;  // an unnamed transition is known by the steps it links
      if (SyntaxNode keyword = transition.child(0)) out.selection = file_range(keyword.range());
    } else if (out.detail.empty()) {
      out.detail = from_to;
    }
    return out;
  }

  // A file of bare VAR blocks and statements: its blocks and steps stand at the top.
  void add_snippet(SyntaxNode root, std::vector<OutlineItem>& items) const {
    for (SyntaxNode child : root.named_children()) {
      if (child.kind() == "var_block") {
        const ast::VarSection section = ast::VarBlock(child).section();
        if (section != ast::VarSection::Global && section != ast::VarSection::Config)
          items.push_back(block_item(child));
      } else if (child.kind() == "sfc_network") {
        add_sfc(child, items);
      }
    }
  }

  const ProjectModel& model_;
  SourceId source_;
  const Document& document_;
};

}  // namespace

std::string cut_text(std::string text, size_t limit) {
  if (text.size() <= limit) return text;
  size_t cut = limit;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  text.resize(cut);
  return text + "...";
}

TextRange name_range_in_file(const ProjectModel& model, const Symbol& symbol) {
  const Document& document = *model.source(symbol.source).document;
  const TextRange name = location_in_file(model, symbol.source, symbol.name_range).range;
  if (name.begin < name.end) return name;
  const uint32_t start = symbol.node ? document.file_offset_of(symbol.node.begin()) : name.begin;
  if (const auto attribute = twincat_element_name(document, start, symbol.name)) return *attribute;
  return {start, start};
}

OutlineKind outline_kind_of(const Symbol& symbol) {
  switch (symbol.kind) {
    case SymbolKind::Program: return OutlineKind::Program;
    case SymbolKind::Function: return OutlineKind::Function;
    case SymbolKind::FunctionBlock: return OutlineKind::FunctionBlock;
    case SymbolKind::Class: return OutlineKind::Class;
    case SymbolKind::Interface: return OutlineKind::Interface;
    case SymbolKind::Method:
      return symbol.owner && symbol.owner->kind == SymbolKind::Property ? OutlineKind::Accessor : OutlineKind::Method;
    case SymbolKind::Property: return OutlineKind::Property;
    case SymbolKind::Action: return OutlineKind::Action;
    case SymbolKind::Transition: return OutlineKind::Transition;
    case SymbolKind::DataType: {
      const std::string_view kind = symbol.node ? symbol.node.kind() : std::string_view();
      if (kind == "struct_type") return OutlineKind::Struct;
      if (kind == "union_type") return OutlineKind::Union;
      if (kind == "enum_type") return OutlineKind::Enum;
      return OutlineKind::Alias;
    }
    case SymbolKind::Variable:
      if (symbol.owner && symbol.owner->kind == SymbolKind::DataType) return OutlineKind::Field;
      return symbol.has(kConstant) ? OutlineKind::Constant : OutlineKind::Variable;
    case SymbolKind::EnumValue: return OutlineKind::EnumValue;
    case SymbolKind::GlobalList:
    case SymbolKind::Namespace: return OutlineKind::GlobalList;
    case SymbolKind::Configuration: return OutlineKind::Configuration;
    case SymbolKind::Resource: return OutlineKind::Resource;
    case SymbolKind::Task: return OutlineKind::Task;
    case SymbolKind::ProgramInstance: return OutlineKind::ProgramInstance;
    case SymbolKind::Step: return OutlineKind::Step;
  }
  return OutlineKind::Variable;
}

std::vector<OutlineItem> document_outline(const ProjectModel& model, SourceId source) {
  if (source >= model.source_count()) return {};
  const SyntaxTree* tree = model.source(source).document->tree();
  if (!tree || tree->aborted()) return {};
  return OutlineBuilder(model, source).build();
}

}  // namespace rung::check::query
