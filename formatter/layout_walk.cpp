#include "formatter/layout_walk.hpp"

#include <algorithm>

#include "formatter/syntax_kinds.hpp"

namespace rung::format {

uint32_t count_line_breaks(std::string_view gap) {
  uint32_t breaks = 0;
  for (size_t i = 0; i < gap.size(); ++i) {
    if (gap[i] == '\n') {
      ++breaks;
    } else if (gap[i] == '\r') {
      ++breaks;
      if (i + 1 < gap.size() && gap[i + 1] == '\n') ++i;
    }
  }
  return breaks;
}

namespace {

using K = NodeKind;

bool is_pou(NodeKind k) {
  switch (k) {
    case K::Program:
    case K::Function:
    case K::FunctionBlock:
    case K::Class:
    case K::Method:
    case K::Property:
    case K::PropertyAccessor:
    case K::Interface:
    case K::Action:
    case K::TransitionDeclaration: return true;
    default: return false;
  }
}

bool is_declaration_item(NodeKind k) {
  return k == K::VarDeclaration || k == K::EmptyDeclaration || k == K::AccessDeclaration;
}

bool is_declaration_list(NodeKind k) {
  return k == K::VarBlock || k == K::GenericConstantBlock || k == K::StructType || k == K::UnionType;
}

// How many levels a child in a body position is indented relative to its parent; -1 when the
// child is no body item (a name, a type, an expression: those continue the parent's line).
int body_delta(NodeKind parent, NodeKind child) {
  switch (parent) {
    case K::SourceFile:
    case K::StatementList:
    case K::IlBody:
    case K::SfcNetwork: return 0;
    case K::IfStatement:
      if (child == K::StatementList) return 1;
      return child == K::ElsifClause || child == K::ElseClause ? 0 : -1;
    case K::ElsifClause:
    case K::ElseClause:
    case K::CaseElement:
    case K::ForStatement:
    case K::WhileStatement:
    case K::RepeatStatement:
    case K::CatchClause:
    case K::FinallyClause: return child == K::StatementList ? 1 : -1;
    case K::TryStatement:
      if (child == K::StatementList) return 1;
      return child == K::CatchClause || child == K::FinallyClause ? 0 : -1;
    case K::CaseStatement:
      if (child == K::CaseElement) return 1;
      return child == K::ElseClause ? 0 : -1;
    case K::VarBlock:
    case K::GenericConstantBlock:
    case K::StructType:
    case K::UnionType: return is_declaration_item(child) ? 1 : -1;
    case K::EnumType: return child == K::EnumValue ? 1 : -1;
    case K::TypeDeclaration:
      return child == K::StructType || child == K::UnionType || child == K::EnumType || child == K::AliasType ? 1 : -1;
    case K::Namespace:
      return is_pou(child) || child == K::UsingDirective || child == K::TypeDeclaration || child == K::VarBlock ||
                     child == K::Namespace
                 ? 1
                 : -1;
    case K::Configuration:
    case K::Resource:
      return child == K::VarBlock || child == K::Resource || child == K::TaskConfiguration ||
                     child == K::ProgramConfiguration
                 ? 1
                 : -1;
    case K::IlInstruction: return child == K::IlInstruction || child == K::IlLabel ? 1 : -1;
    case K::SfcStep: return child == K::SfcAction ? 1 : -1;
    case K::SfcTransition:
    case K::SfcActionBlock: return child == K::StatementList || child == K::IlBody ? 1 : -1;
    default: break;
  }
  if (is_pou(parent)) {
    // A POU's parts stay at its level: each has its own editor in CODESYS and TwinCAT.
    switch (child) {
      case K::VarBlock:
      case K::GenericConstantBlock:
      case K::TypeDeclaration:
      case K::StatementList:
      case K::IlBody:
      case K::SfcNetwork: return 0;
      default: return is_pou(child) ? 0 : -1;
    }
  }
  return -1;
}

// Nodes whose own tokens (keywords, END_..., the ';' after them) stand at the node's level even
// when they start a line; the tokens of other nodes continue a line.
bool is_block(NodeKind k) {
  switch (k) {
    case K::SourceFile:
    case K::StatementList:
    case K::IfStatement:
    case K::ElsifClause:
    case K::ElseClause:
    case K::CaseStatement:
    case K::CaseElement:
    case K::ForStatement:
    case K::WhileStatement:
    case K::RepeatStatement:
    case K::TryStatement:
    case K::CatchClause:
    case K::FinallyClause:
    case K::VarBlock:
    case K::GenericConstantBlock:
    case K::StructType:
    case K::UnionType:
    case K::EnumType:
    case K::TypeDeclaration:
    case K::Namespace:
    case K::Configuration:
    case K::Resource:
    case K::IlBody:
    case K::IlInstruction:
    case K::SfcNetwork:
    case K::SfcStep:
    case K::SfcTransition:
    case K::SfcActionBlock: return true;
    default: return is_pou(k);
  }
}

// The indentation of a block's body relative to the block: where a comment line before its
// closing keyword goes.
int inner_delta(NodeKind k) {
  switch (k) {
    case K::IfStatement:
    case K::CaseStatement:
    case K::ForStatement:
    case K::WhileStatement:
    case K::RepeatStatement:
    case K::TryStatement:
    case K::VarBlock:
    case K::GenericConstantBlock:
    case K::StructType:
    case K::UnionType:
    case K::EnumType:
    case K::Namespace:
    case K::Configuration:
    case K::Resource:
    case K::IlInstruction:
    case K::SfcStep:
    case K::SfcTransition:
    case K::SfcActionBlock: return 1;
    default: return 0;
  }
}

// Nodes whose tokens keep the spacing the user typed: INT#5, FB_Buffer<100>, T...
bool is_glued(NodeKind k) {
  return k == K::TypedLiteral || k == K::GenericType || k == K::VariadicType;
}

// Nodes whose text is line-based (IL, a top-level expression line): never broken.
bool is_line_based(NodeKind k) {
  return k == K::IlBody || k == K::IlInstruction || k == K::IlExpression || k == K::ExpressionFragment;
}

Role role_of(const SymbolInfo& info, NodeKind parent) {
  if (info.named) return info.keyword ? Role::Keyword : Role::Word;
  switch (info.token) {
    case TokenClass::Keyword:
      if (parent == K::BinaryExpression) return Role::BinaryWordOp;
      if (parent == K::UnaryExpression) return Role::UnaryWordOp;
      return Role::Keyword;
    case TokenClass::Comma: return Role::Comma;
    case TokenClass::Semicolon: return Role::Semicolon;
    case TokenClass::OpenParen:
      switch (parent) {
        case K::ArgumentList:
        case K::StringType:
        case K::SubrangeType:
        case K::RepeatedInitializer:
        case K::SfcAction:
        case K::SfcStepMacro:
        case K::CatchClause: return Role::OpenCall;
        case K::IlInstruction: return Role::OpenIl;
        default: return Role::OpenGroup;
      }
    case TokenClass::CloseParen:
    case TokenClass::CloseBracket: return Role::Close;
    case TokenClass::OpenBracket:
      return parent == K::IndexExpression || parent == K::ArrayType || parent == K::StringType ||
                     parent == K::ArgumentLists
                 ? Role::OpenIndex
                 : Role::OpenInit;
    case TokenClass::Dot: return parent == K::GlobalReference ? Role::GlobalDot : Role::Dot;
    case TokenClass::Range: return Role::Range;
    case TokenClass::Caret: return Role::Caret;
    case TokenClass::At: return Role::At;
    case TokenClass::Colon:
      switch (parent) {
        case K::Label:
        case K::IlLabel:
        case K::CaseElement:
        case K::SfcStep:
        case K::Action:
        case K::TransitionDeclaration:
        case K::SfcActionBlock: return Role::LabelColon;
        default: return Role::DeclColon;
      }
    case TokenClass::Assign: return Role::Assign;
    case TokenClass::Operator:
      if (parent == K::BinaryExpression) return Role::BinaryOp;
      if (parent == K::UnaryExpression) return Role::UnaryOp;
      return Role::Other;
    default: break;
  }
  return Role::Other;
}

struct Frame {
  SyntaxNode node;
  NodeKind kind = K::Other;
  uint32_t begin = 0;
  int32_t level = 0;
  int32_t cont = 1;
  uint32_t child_count = 0;
  uint32_t first_leaf = 0;  // index of the first leaf inside the node
  uint32_t glue = 0;
  int32_t row = -1;        // index into WalkResult::rows
  int32_t outer_row = -1;  // the row around this node (a declaration around inline STRUCT fields)
  bool block = false;
  bool had_body_item = false;
  bool line_based = false;
};

class Walker {
 public:
  Walker(const SyntaxTree& tree, std::string_view text, const WalkOptions& options)
      : tree_(tree), text_(text), options_(options) {
    condition_field_ = NodeTable::field_id("condition");
  }

  WalkResult run() {
    SyntaxNode root = tree_.root();
    if (!root) return std::move(out_);
    out_.leaves.reserve(text_.size() / 4 + 16);
    Frame top;
    top.node = root;
    top.kind = symbol_info(root.symbol()).node;
    top.begin = root.begin();
    top.level = 0;
    top.cont = 1;
    top.child_count = root.child_count();
    top.block = true;
    stack_.push_back(top);

    const NodeTable* table = root.table();
    for (uint32_t i = root.index() + 1; i < root.subtree_end();) {
      const SyntaxNode node(table, i);
      // Leave the nodes whose subtrees ended (never the root's frame).
      while (stack_.size() > 1 && stack_.back().node.subtree_end() <= i) pop();
      const bool has_children = node.subtree_end() > i + 1;
      const bool pragma = has_children && node.is_extra() && symbol_info(node.symbol()).node == K::Pragma;
      if (!has_children || pragma) {
        leaf(node);
        i = node.subtree_end();
      } else {
        enter(node, node.child_count(), options_.collect_breaks ? node.field_id() : TSFieldId{0});
        ++i;
      }
    }
    while (stack_.size() > 1) pop();
    return std::move(out_);
  }

 private:
  void pop() {
    current_row_ = stack_.back().outer_row;
    stack_.pop_back();
  }

  bool added_break_at(uint32_t index) const {
    const std::vector<uint32_t>* breaks = options_.added_breaks;
    return breaks && std::binary_search(breaks->begin(), breaks->end(), index);
  }

  // Whether a node or leaf starting at `begin` is the first code on its line.
  bool starts_line(uint32_t begin) const {
    if (added_break_at(static_cast<uint32_t>(out_.leaves.size()))) return true;
    if (begin > last_end_ && count_line_breaks(text_.substr(last_end_, begin - last_end_)) > 0) return true;
    return !line_has_code_;
  }

  void enter(SyntaxNode node, uint32_t children, TSFieldId field) {
    Frame& parent = stack_.back();
    Frame f;
    f.node = node;
    f.kind = symbol_info(node.symbol()).node;
    f.begin = node.begin();
    f.child_count = children;
    f.first_leaf = static_cast<uint32_t>(out_.leaves.size());
    f.block = is_block(f.kind);
    f.glue = parent.glue ? parent.glue : (is_glued(f.kind) ? f.begin + 1 : 0);
    f.line_based = parent.line_based || is_line_based(f.kind);

    const int delta = body_delta(parent.kind, f.kind);
    if (delta >= 0) {
      const bool type_item = parent.kind == K::TypeDeclaration;
      f.level = type_item && !starts_line(f.begin) ? line_level_ : parent.level + delta;
      if (delta > 0 && !parent.had_body_item) {
        parent.had_body_item = true;
        // The last token before the first body item opens the block (THEN, DO, VAR, OF, ':').
        if (last_code_ != kNoLeaf && last_code_ >= parent.first_leaf) out_.leaves[last_code_].opens_block = true;
      }
    } else if (f.begin == parent.begin) {
      f.level = parent.level;
    } else if (starts_line(f.begin)) {
      f.level = parent.cont;
    } else {
      f.level = line_level_;
    }
    f.cont = f.level + 1;

    f.outer_row = current_row_;
    const bool instruction =
        f.kind == K::IlInstruction && (parent.kind == K::IlBody || parent.kind == K::IlInstruction);
    if (f.kind == K::VarDeclaration || instruction) {
      f.row = static_cast<int32_t>(out_.rows.size());
      current_row_ = f.row;
      AlignedRow row;
      row.first = f.first_leaf;
      row.il = instruction;
      row.group = is_declaration_list(parent.kind) || instruction ? parent.begin : node.begin();
      out_.rows.push_back(row);
    }
    if (options_.collect_breaks) {
      if (field == condition_field_ && field != 0 &&
          (parent.kind == K::IfStatement || parent.kind == K::ElsifClause || parent.kind == K::WhileStatement ||
           parent.kind == K::RepeatStatement)) {
        out_.conditions.push_back(node);
      }
      if (f.kind == K::ArgumentList && !f.line_based) out_.argument_lists.push_back(node);
    }
    stack_.push_back(f);
  }

  void leaf(SyntaxNode node) {
    const uint32_t begin = node.begin();
    const uint32_t end = std::min<uint32_t>(node.end(), static_cast<uint32_t>(text_.size()));
    if (end <= begin || begin < last_end_) return;  // zero-width tokens (IL line ends)
    Frame& parent = stack_.back();
    const SymbolInfo& info = symbol_info(node.symbol());

    Leaf l;
    l.begin = begin;
    l.end = end;
    const std::string_view gap = text_.substr(last_end_, begin - last_end_);
    l.newlines = count_line_breaks(gap);
    l.space_before = !gap.empty();
    const uint32_t index = static_cast<uint32_t>(out_.leaves.size());
    if (l.newlines == 0 && index > 0 && added_break_at(index)) l.newlines = 1;
    if (l.newlines > 0) line_has_code_ = false;
    const std::string_view text = text_.substr(begin, end - begin);

    const bool trivia = node.is_extra() && (info.node == K::Comment || info.node == K::Pragma);
    if (trivia) {
      l.role = Role::Trivia;
      l.multiline = text.find_first_of("\r\n") != std::string_view::npos;
      l.line_comment = text.size() >= 2 && text[0] == '/' && text[1] == '/';
    } else {
      l.role = role_of(info, parent.kind);
      LeafPlace place{parent.kind, begin == parent.begin, parent.child_count == 1};
      l.case_class = case_class(info, place, text);
      l.glue = parent.glue;
      const bool first = begin == parent.begin;
      bool own_level = first || l.role == Role::Close;
      if (!own_level && parent.block) own_level = !continues_block_line(parent.kind, l.role, text);
      l.level = own_level ? parent.level : parent.cont;
      l.comment_level = l.level;
      if (parent.block && info.closer) l.comment_level = parent.level + inner_delta(parent.kind);
      if (info.middle && first) l.comment_level = parent.level + 1;
      if (l.role == Role::Close && parent.block) l.comment_level = parent.level + inner_delta(parent.kind);
      if (!line_has_code_) {
        line_level_ = l.level;
        line_has_code_ = true;
      }
      last_code_ = index;
      if (parent.row >= 0) {
        AlignedRow& row = out_.rows[static_cast<size_t>(parent.row)];
        if (!row.il && l.role == Role::DeclColon && row.column == kNoLeaf) row.column = index;
        if (!row.il && l.role == Role::Assign && row.assign == kNoLeaf) row.assign = index;
      }
      if (current_row_ >= 0) {
        // An IL instruction's operand: its first token after the operator.
        AlignedRow& row = out_.rows[static_cast<size_t>(current_row_)];
        if (row.il && row.column == kNoLeaf && index > row.first) row.column = index;
      }
    }
    out_.leaves.push_back(l);
    last_end_ = end;
    // Every leaf of a row, its last one included, passes here: the last one seen wins.
    if (!trivia && current_row_ >= 0) out_.rows[static_cast<size_t>(current_row_)].last = index;
  }

  // Tokens of a block statement that continue its first line when they start a line of their
  // own: FOR i := 1 / TO 10 / BY 2, and the ',' and ':' of a CASE label list.
  static bool continues_block_line(NodeKind block, Role role, std::string_view text) {
    if (block == K::ForStatement)
      return role == Role::Assign || equal_ignoring_case(text, "TO") || equal_ignoring_case(text, "BY");
    if (block == K::CaseElement) return role == Role::Comma || role == Role::LabelColon;
    return false;
  }

  const SyntaxTree& tree_;
  std::string_view text_;
  const WalkOptions& options_;
  TSFieldId condition_field_ = 0;
  WalkResult out_;
  std::vector<Frame> stack_;
  uint32_t last_end_ = 0;
  uint32_t last_code_ = kNoLeaf;
  int32_t line_level_ = 0;
  int32_t current_row_ = -1;
  bool line_has_code_ = false;
};

}  // namespace

WalkResult walk_leaves(const SyntaxTree& tree, std::string_view text, const WalkOptions& options) {
  return Walker(tree, text, options).run();
}

}  // namespace rung::format
