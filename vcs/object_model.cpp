#include "vcs/object_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

#include "formatter/format.hpp"
#include "parser/ast.hpp"
#include "parser/containers/read_container.hpp"
#include "parser/file_walk.hpp"
#include "parser/keywords.hpp"
#include "parser/source/decode.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::vcs {
namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

// Blanks collapsed to one space, none at the ends.
std::string collapse_blanks(std::string_view text) {
  std::string out;
  bool blank = false;
  for (const char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      blank = !out.empty();
      continue;
    }
    if (blank) out += ' ';
    blank = false;
    out += c;
  }
  return out;
}

// The normal form of the code of a subtree (see the header): tokens inside [begin, end) and
// outside every excluded subtree, joined by single spaces.
class KeyBuilder {
 public:
  KeyBuilder(bool comments, std::string_view self_name) : comments_(comments), self_name_(self_name) {}

  void exclude(SyntaxNode node) {
    if (node) excluded_.emplace_back(node.index(), node.subtree_end());
  }

  std::string key(SyntaxNode root) { return key(root, root.begin(), root.end()); }

  std::string key(SyntaxNode root, uint32_t begin, uint32_t end) {
    std::string out;
    walk_preorder(root, [&](SyntaxNode node) {
      if (node.end() <= begin && node.begin() < begin) return false;
      if (node.begin() >= end && node.end() > node.begin()) return false;
      if (is_excluded(node)) return false;
      const std::string_view kind = node.kind();
      if (kind == "comment") {
        if (comments_) append(out, collapse_blanks(node.text()));
        return false;
      }
      if (kind == "pragma") {
        append(out, collapse_blanks(node.text()));
        return false;
      }
      if (node.child_count() > 0) return true;
      if (node.begin() < begin || node.end() > end) return false;
      append(out, token_key(node));
      return false;
    });
    return out;
  }

 private:
  bool is_excluded(SyntaxNode node) const {
    return std::any_of(excluded_.begin(), excluded_.end(),
                       [&](const auto& range) { return node.index() >= range.first && node.index() < range.second; });
  }

  std::string token_key(SyntaxNode node) const {
    const std::string_view text = node.text();
    if (text.empty()) return {};  // a MISSING token error recovery made up
    if (!node.is_named()) {
      // Keywords are aliased to their upper-case spelling; punctuation is its own kind.
      const std::string_view kind = node.kind();
      return equal_ignoring_case(kind, text) ? std::string(kind) : std::string(text);
    }
    const std::string_view kind = node.kind();
    if (kind.find("string") != std::string_view::npos) return std::string(text);
    if (!self_name_.empty() && equal_ignoring_case(text, self_name_)) return "\x01";
    if (kind == "identifier") return std::string(text);
    return keywords::upper(text);
  }

  static void append(std::string& out, std::string_view token) {
    if (token.empty()) return;
    if (!out.empty()) out += ' ';
    out += token;
  }

  bool comments_;
  std::string_view self_name_;
  std::vector<std::pair<uint32_t, uint32_t>> excluded_;
};

// The lines holding [begin, end) with their common indentation removed and no trailing blanks.
std::string dedented_lines(std::string_view text, uint32_t begin, uint32_t end) {
  size_t line_begin = text.rfind('\n', begin == 0 ? 0 : begin - 1);
  line_begin = (line_begin == std::string_view::npos || begin == 0) ? 0 : line_begin + 1;
  if (text.substr(line_begin, begin - line_begin).find_first_not_of(" \t") != std::string_view::npos) {
    line_begin = begin;  // code before it on the line: start at the node
  }
  std::vector<std::string_view> lines;
  std::string_view rest = text.substr(line_begin, end - line_begin);
  while (!rest.empty()) {
    const size_t nl = rest.find('\n');
    std::string_view line = rest.substr(0, nl);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    lines.push_back(line);
    if (nl == std::string_view::npos) break;
    rest.remove_prefix(nl + 1);
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  size_t indent = std::string_view::npos;
  for (const std::string_view line : lines) {
    if (line.empty()) continue;
    indent = std::min(indent, std::min(line.find_first_not_of(" \t"), line.size()));
  }
  if (indent == std::string_view::npos) indent = 0;
  std::string out;
  for (const std::string_view line : lines) {
    out.append(line.size() >= indent ? line.substr(indent) : std::string_view());
    out += '\n';
  }
  return out;
}

std::string block_label(const ast::VarBlock& block) {
  std::string label(ast::var_section_name(block.section()));
  for (const std::string_view q : {"CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"}) {
    if (block.has_qualifier(q)) label += fmt::format(" {}", q);
  }
  return label;
}

class ModelReader {
 public:
  ModelReader(const SyntaxTree& tree, std::string path, bool comments, const containers::ContainerDocument* container,
              std::string_view gvl_default_name)
      : tree_(tree),
        text_(tree.text()),
        path_(std::move(path)),
        comments_(comments),
        container_(container),
        gvl_default_name_(gvl_default_name) {}

  std::vector<Object> read() {
    const ast::Outline outline = ast::outline(tree_.root());
    std::vector<std::pair<uint32_t, Object>> objects;
    for (const ast::Pou& pou : outline.pous) objects.emplace_back(pou.node().begin(), read_pou(pou));
    for (const ast::TypeDeclaration& type : outline.types) objects.emplace_back(type.node().begin(), read_type(type));
    read_gvls(outline.global_blocks, objects);
    for (const SyntaxNode& configuration : outline.configurations) {
      objects.emplace_back(configuration.begin(), read_configuration(configuration));
    }
    std::stable_sort(objects.begin(), objects.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Object> out;
    out.reserve(objects.size());
    for (auto& [at, object] : objects) out.push_back(std::move(object));
    return out;
  }

 private:
  // The node directly below the root holding `node` (a TYPE block holds several types).
  SyntaxNode top_level_of(SyntaxNode node) const {
    SyntaxNode at = node;
    while (at.parent() && at.parent().parent()) at = at.parent();
    return at;
  }

  // Where the text belonging to a top-level item starts: the end of the previous item's node.
  uint32_t leading_begin(uint32_t item_begin) const {
    uint32_t begin = 0;
    const SyntaxNode root = tree_.root();
    root.for_each_child([&](SyntaxNode child) {
      if (child.end() <= item_begin && child.kind() != "pragma" && child.kind() != "comment") {
        begin = std::max(begin, child.end());
      }
    });
    return begin;
  }

  // The pragmas (and comments, with --comments) written before a top-level item.
  std::string leading_key(uint32_t item_begin, std::string_view self) const {
    KeyBuilder keys(comments_, self);
    return keys.key(tree_.root(), leading_begin(item_begin), item_begin);
  }

  std::string formatted_text(SyntaxNode node) const { return dedented_lines(text_, node.begin(), node.end()); }

  Declaration read_declaration(const ast::VarDeclaration& declaration, SyntaxNode name, std::string block,
                               std::string attributes, std::string_view self) const {
    const ast::VarDeclaration::Parts parts = declaration.parts();
    KeyBuilder keys(comments_, self);
    Declaration d;
    d.block = std::move(block);
    d.name = std::string(name.text());
    d.type_key = parts.type ? keys.key(parts.type) : std::string();
    d.value_key = parts.initial_value ? keys.key(parts.initial_value) : std::string();
    if (parts.location) d.other_key = "AT " + keys.key(parts.location);
    if (parts.init_arguments) d.other_key += (d.other_key.empty() ? "" : " ") + keys.key(parts.init_arguments);
    d.attributes = std::move(attributes);
    d.text = d.name;
    if (parts.location) d.text += fmt::format(" AT {}", parts.location.text());
    if (parts.type) d.text += fmt::format(" : {}", collapse_blanks(parts.type.text()));
    if (parts.init_arguments) d.text += collapse_blanks(parts.init_arguments.text());
    if (parts.initial_value) d.text += fmt::format(" := {}", collapse_blanks(parts.initial_value.text()));
    if (comments_) d.comment = comments_near(declaration.node());
    return d;
  }

  // Comments inside a declaration and on the rest of its line.
  std::string comments_near(SyntaxNode node) const {
    size_t line_end = text_.find('\n', node.end());
    if (line_end == std::string_view::npos) line_end = text_.size();
    KeyBuilder keys(true, {});
    std::string out;
    walk_preorder(tree_.root(), [&](SyntaxNode n) {
      if (n.end() < node.begin() || n.begin() > line_end) return false;
      if (n.kind() == "comment" && n.begin() >= node.begin() && n.begin() <= line_end) {
        if (!out.empty()) out += ' ';
        out += collapse_blanks(n.text());
        return false;
      }
      return true;
    });
    return out;
  }

  // The declarations of VAR blocks, each with the pragmas written before it inside its block.
  void read_blocks(const std::vector<ast::VarBlock>& blocks, std::string_view self,
                   std::vector<Declaration>& out) const {
    for (const ast::VarBlock& block : blocks) {
      const std::string label = block_label(block);
      std::vector<SyntaxNode> pragmas;
      for_each_pragma(block.node(), [&](SyntaxNode pragma) { pragmas.push_back(pragma); });
      size_t next_pragma = 0;
      for (const ast::VarDeclaration& declaration : block.declarations()) {
        std::string attributes;
        while (next_pragma < pragmas.size() && pragmas[next_pragma].end() <= declaration.node().begin()) {
          if (!attributes.empty()) attributes += ' ';
          attributes += collapse_blanks(pragmas[next_pragma].text());
          ++next_pragma;
        }
        for (const SyntaxNode& name : declaration.names()) {
          out.push_back(read_declaration(declaration, name, label, attributes, self));
        }
      }
    }
  }

  std::string accessor_name(const ast::Pou& pou) const {
    const std::string_view name = pou.name();
    if (!name.empty()) return std::string(name);
    const SyntaxNode first = pou.node().child(0);
    return first ? keywords::upper(first.text()) : std::string("ACCESSOR");
  }

  void read_part(const ast::Pou& pou, const std::string& qualified, std::string_view self, std::vector<Part>& parts,
                 std::string_view leading) const {
    Part part;
    part.name = qualified;
    part.kind =
        pou.kind() == ast::PouKind::PropertyAccessor ? accessor_name(pou) : std::string(ast::pou_kind_name(pou.kind()));
    KeyBuilder header(comments_, self);
    KeyBuilder declaration(comments_, self);
    for (const ast::VarBlock& block : pou.var_blocks()) header.exclude(block.node());
    const SyntaxNode body = pou.body();
    header.exclude(body);
    declaration.exclude(body);
    for (const ast::Pou& member : pou.members()) {
      header.exclude(member.node());
      declaration.exclude(member.node());
    }
    const std::string leading_text(leading);
    part.header_key = leading_text + (leading_text.empty() ? "" : " ") + header.key(pou.node());
    part.declaration_key = leading_text + (leading_text.empty() ? "" : " ") + declaration.key(pou.node());
    read_blocks(pou.var_blocks(), self, part.declarations);
    const uint32_t declaration_end = body ? body.begin() : pou.node().end();
    uint32_t end = declaration_end;
    for (const ast::Pou& member : pou.members()) {
      if (member.node().begin() > pou.node().begin() && member.node().begin() < end) end = member.node().begin();
    }
    part.declaration_text = dedented_lines(text_, pou.node().begin(), end);
    if (body) {
      KeyBuilder body_keys(comments_, self);
      part.has_body = true;
      part.body_key = body_keys.key(body);
      part.body_text = formatted_text(body);
    }
    parts.push_back(std::move(part));
    for (const ast::Pou& member : pou.members()) {
      const std::string name =
          member.kind() == ast::PouKind::PropertyAccessor ? accessor_name(member) : std::string(member.name());
      std::string member_name = qualified;
      if (!member_name.empty()) member_name += '.';
      member_name += name;
      read_part(member, member_name, self, parts, {});
    }
  }

  Object read_pou(const ast::Pou& pou) const {
    Object object;
    object.kind = std::string(ast::pou_kind_name(pou.kind()));
    object.name = std::string(pou.name());
    object.path = path_;
    const std::string leading = leading_key(pou.node().begin(), object.name);
    read_part(pou, "", object.name, object.parts, leading);
    return object;
  }

  Object read_type(const ast::TypeDeclaration& type) const {
    Object object;
    object.kind = "TYPE";
    object.name = std::string(type.name());
    object.path = path_;
    Part part;
    part.kind = "TYPE";
    KeyBuilder header(comments_, object.name);
    KeyBuilder whole(comments_, object.name);
    const std::vector<ast::VarDeclaration> fields = type.fields();
    for (const ast::VarDeclaration& field : fields) header.exclude(field.node());
    const std::vector<SyntaxNode> values = type.enum_values();
    for (const SyntaxNode& value : values) header.exclude(value);
    const std::string leading = leading_key(top_level_of(type.node()).begin(), object.name);
    part.header_key = leading + (leading.empty() ? "" : " ") + header.key(type.node());
    part.declaration_key = leading + (leading.empty() ? "" : " ") + whole.key(type.node());
    part.declaration_text = formatted_text(type.node());
    const std::string block = type.kind() == ast::TypeKind::Union ? "UNION" : "STRUCT";
    for (const ast::VarDeclaration& field : fields) {
      for (const SyntaxNode& name : field.names()) {
        part.declarations.push_back(read_declaration(field, name, block, {}, object.name));
      }
    }
    for (const SyntaxNode& value : values) {
      KeyBuilder keys(comments_, object.name);
      Declaration d;
      d.block = "ENUM";
      d.name = std::string(value.child_by_field("name").text());
      const SyntaxNode v = value.child_by_field("value");
      d.value_key = v ? keys.key(v) : std::string();
      d.text = v ? fmt::format("{} := {}", d.name, collapse_blanks(v.text())) : d.name;
      part.declarations.push_back(std::move(d));
    }
    object.parts.push_back(std::move(part));
    return object;
  }

  // GVL name: the container object holding the block, else the file's name.
  std::string gvl_name(const ast::VarBlock& block) const {
    if (container_ != nullptr) {
      // The tree text is the formatted virtual text, whose offsets differ: objects are in order,
      // and a TwinCAT or .EXP GVL file names its object; take the first GVL object.
      for (const containers::ContainerObject& object : container_->objects) {
        if (object.kind == "GVL") return object.name;
      }
    }
    (void)block;
    return std::string(gvl_default_name_);
  }

  void read_gvls(const std::vector<ast::VarBlock>& blocks, std::vector<std::pair<uint32_t, Object>>& objects) const {
    if (blocks.empty()) return;
    Object object;
    object.kind = "GVL";
    object.name = gvl_name(blocks.front());
    object.path = path_;
    Part part;
    part.kind = "GVL";
    std::string declaration_key;
    std::string declaration_text;
    for (const ast::VarBlock& block : blocks) {
      KeyBuilder keys(comments_, {});
      const std::string leading = leading_key(block.node().begin(), {});
      if (!leading.empty()) part.header_key += (part.header_key.empty() ? "" : " ") + leading;
      declaration_key +=
          (declaration_key.empty() ? "" : " ") + leading + (leading.empty() ? "" : " ") + keys.key(block.node());
      declaration_text += dedented_lines(text_, block.node().begin(), block.node().end());
    }
    part.declaration_key = std::move(declaration_key);
    part.declaration_text = std::move(declaration_text);
    read_blocks(blocks, {}, part.declarations);
    object.parts.push_back(std::move(part));
    objects.emplace_back(blocks.front().node().begin(), std::move(object));
  }

  Object read_configuration(SyntaxNode configuration) const {
    Object object;
    object.kind = "CONFIGURATION";
    object.name = std::string(configuration.child_by_field("name").text());
    object.path = path_;
    Part part;
    part.kind = "CONFIGURATION";
    KeyBuilder keys(comments_, object.name);
    part.declaration_key = keys.key(configuration);
    part.header_key = part.declaration_key;
    part.declaration_text = formatted_text(configuration);
    object.parts.push_back(std::move(part));
    return object;
  }

  const SyntaxTree& tree_;
  std::string_view text_;
  std::string path_;
  bool comments_;
  const containers::ContainerDocument* container_;
  std::string_view gvl_default_name_;
};

std::string file_stem(std::string_view path) {
  const size_t slash = path.find_last_of("/\\");
  std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const size_t dot = name.rfind('.');
  if (dot != std::string_view::npos && dot > 0) name = name.substr(0, dot);
  return std::string(name);
}

// A file read up to the text the grammar sees, laid out by the formatter.
struct ReadText {
  std::string text;
  std::optional<containers::ContainerDocument> container;
  std::vector<std::string> errors;
  std::vector<std::string> notes;
};

ReadText read_text(std::string_view path, std::string_view bytes) {
  ReadText r;
  const source::DecodedText decoded = source::decode(bytes);
  if (decoded.is_binary) {
    r.errors.emplace_back("binary file; not PLC source");
    return r;
  }
  containers::ContainerDocument container = containers::read_container(path, decoded.utf8);
  if (container.kind == containers::ContainerKind::Unsupported) {
    r.notes.emplace_back("holds no PLC source");
    return r;
  }
  bool flat_comments = false;
  for (const containers::ContainerIssue& issue : container.issues) r.errors.push_back(issue.message);
  for (const containers::ContainerObject& object : container.objects) {
    if (!object.note.empty()) r.notes.push_back(fmt::format("{}: {}", object.name, object.note));
    flat_comments = flat_comments || !object.nested_comments;
  }
  format::FormatRequest request;
  request.flat_comments = flat_comments;
  format::FormatResult formatted = format::format_text(container.virtual_text, project::FormatSettings{}, request);
  const std::string& text = formatted.status == format::Status::Formatted ? formatted.text : container.virtual_text;
  // One line end: CRLF files (TwinCAT writes them) read as LF, so no '\r' reaches a diff.
  r.text.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r' || i + 1 >= text.size() || text[i + 1] != '\n') r.text += text[i];
  }
  if (container.kind != containers::ContainerKind::None) r.container = std::move(container);
  return r;
}

}  // namespace

std::string_view Object::name_space() const {
  if (kind == "TYPE") return "type";
  if (kind == "GVL") return "gvl";
  if (kind == "CONFIGURATION") return "configuration";
  return "pou";
}

std::string Object::content_key() const {
  std::string key = kind;
  for (const Part& part : parts) {
    key += '\x02';
    key += part.name;
    key += '\x02';
    key += part.declaration_key;
    key += '\x02';
    key += part.body_key;
  }
  return key;
}

FileObjects read_objects(std::string_view path, std::string_view bytes, const ReadOptions& options) {
  FileObjects file;
  file.path = std::string(path);
  ReadText read = read_text(path, bytes);
  file.errors = std::move(read.errors);
  file.notes = std::move(read.notes);
  if (read.text.empty()) return file;
  const SyntaxTree tree = SyntaxTree::parse(std::move(read.text));
  if (tree.aborted()) {
    file.errors.emplace_back("parsing stopped: the file is too large or too deeply nested");
    return file;
  }
  const std::string stem = file_stem(path);
  ModelReader reader(tree, file.path, options.comments, read.container ? &*read.container : nullptr, stem);
  file.objects = reader.read();
  return file;
}

// Without the "(* @PATH := '...' *)" marker lines of a CODESYS export (export bookkeeping).
std::string without_export_markers(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl == std::string_view::npos ? text.size() : nl + 1);
    const std::string trimmed = collapse_blanks(line);
    const bool marker = trimmed.rfind("(* @", 0) == 0 && trimmed.size() >= 6 &&
                        trimmed.compare(trimmed.size() - 2, 2, "*)") == 0 && trimmed.find("*)") == trimmed.size() - 2;
    if (!marker) out += line;
    text.remove_prefix(line.size());
  }
  return out;
}

TextView text_view(std::string_view path, std::string_view bytes) {
  ReadText read = read_text(path, bytes);
  TextView view;
  view.text = read.container && read.container->kind == containers::ContainerKind::CodesysExp
                  ? without_export_markers(read.text)
                  : std::move(read.text);
  if (!view.text.empty() && view.text.back() != '\n') view.text += '\n';
  view.errors = std::move(read.errors);
  view.notes = std::move(read.notes);
  return view;
}

bool is_plc_source_path(std::string_view path, std::string_view bytes) {
  const SourceKind kind = source_kind_of(std::filesystem::path(std::string(path)));
  if (kind != SourceKind::None) return true;
  std::string lower(path);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".xml") == 0 && !bytes.empty()) {
    return containers::detect_container(path, bytes.substr(0, 8192)) == containers::ContainerKind::PlcOpen;
  }
  return false;
}

}  // namespace rung::vcs
