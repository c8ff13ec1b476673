#include "parser/containers/plcopen_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "parser/containers/xml_text.hpp"
#include "parser/source/line_index.hpp"

namespace rung::containers {
namespace {

// As in the TwinCAT reader: node values stay byte-identical to the file so that
// offset_debug() locates them; entities are expanded by append_escaped_text.

constexpr std::string_view codesys_data = "http://www.3s-software.com/plcopenxml/";

// The element name without its namespace prefix ("xhtml:p" -> "p").
std::string_view local_name(pugi::xml_node node) {
  const std::string_view name = node.name();
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

pugi::xml_node child(pugi::xml_node parent, std::string_view name) {
  for (const pugi::xml_node c : parent.children()) {
    if (c.type() == pugi::node_element && local_name(c) == name) return c;
  }
  return {};
}

std::vector<pugi::xml_node> children(pugi::xml_node parent, std::string_view name) {
  std::vector<pugi::xml_node> out;
  for (const pugi::xml_node c : parent.children()) {
    if (c.type() == pugi::node_element && local_name(c) == name) out.push_back(c);
  }
  return out;
}

// The only element child of a type container (<type>, <baseType>, <returnType>).
pugi::xml_node first_element(pugi::xml_node parent) {
  for (const pugi::xml_node c : parent.children()) {
    if (c.type() == pugi::node_element && local_name(c) != "addData" && local_name(c) != "documentation") return c;
  }
  return {};
}

bool is_true(pugi::xml_node element, const char* attribute) {
  const std::string_view value = element.attribute(attribute).value();
  return value == "true" || value == "1";
}

bool is_blank(std::string_view s) {
  return s.find_first_not_of(" \t\r\n") == std::string_view::npos;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// addData/data elements of `owner` whose name is the CODESYS one ending in `kind`.
std::vector<pugi::xml_node> codesys_data_of(pugi::xml_node owner, std::string_view kind) {
  std::vector<pugi::xml_node> out;
  for (const pugi::xml_node data : children(child(owner, "addData"), "data")) {
    const std::string_view name = data.attribute("name").value();
    if (name.substr(0, codesys_data.size()) == codesys_data && name.substr(codesys_data.size()) == kind) {
      out.push_back(data);
    }
  }
  return out;
}

// An xsd:duration such as "PT0.02S" (CODESYS task intervals) as an IEC time
// literal ("T#0.02S"); other values (Beremiz writes "T#100ms") unchanged.
std::string iec_interval(std::string_view value) {
  if (value.size() < 3 || value.substr(0, 2) != "PT") return std::string(value);
  std::string out = "T#";
  std::string number;
  for (const char c : value.substr(2)) {
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      number += c;
    } else if ((c == 'H' || c == 'M' || c == 'S') && !number.empty()) {
      out += number;
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      number.clear();
    } else {
      return std::string(value);
    }
  }
  return number.empty() && out.size() > 2 ? out : std::string(value);
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// An IEC identifier: a letter or '_', then letters, digits and '_'. Bytes of
// UTF-8 characters are accepted as letters (CODESYS allows them in names).
bool is_identifier(std::string_view name) {
  if (name.empty()) return false;
  const auto letter = [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80;
  };
  if (!letter(name.front())) return false;
  return std::all_of(name.begin(), name.end(),
                     [&](char c) { return letter(c) || std::isdigit(static_cast<unsigned char>(c)); });
}

// Skips blanks and ST comments ((* *), /* */, //) from `at`; returns where code starts.
size_t skip_blanks_and_comments(std::string_view s, size_t at) {
  while (at < s.size()) {
    const char c = s[at];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++at;
    } else if (s.compare(at, 2, "(*") == 0 || s.compare(at, 2, "/*") == 0) {
      const size_t close = s.find(s[at] == '(' ? "*)" : "*/", at + 2);
      if (close == std::string_view::npos) return s.size();
      at = close + 2;
    } else if (s.compare(at, 2, "//") == 0) {
      const size_t eol = s.find('\n', at);
      if (eol == std::string_view::npos) return s.size();
      at = eol + 1;
    } else {
      break;
    }
  }
  return at;
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

// What an ST body really holds when it is not ST: OpenPLC Editor v4 stores C/C++
// (Arduino) and Python blocks in <ST>. "" when the text looks like ST.
std::string_view foreign_language(std::string_view code) {
  const size_t begin = skip_blanks_and_comments(code, 0);
  const std::string_view first = code.substr(begin, code.find('\n', begin) - begin);
  for (const std::string_view directive : {"#include", "#define", "#pragma", "#ifdef", "#ifndef"}) {
    if (starts_with(first, directive)) return "C/C++";
  }
  // Python: "import x", "from x import y", "def f(...):" at the start of a line.
  const auto python_line = [](std::string_view line) {
    if (starts_with(line, "import ") ||
        (starts_with(line, "from ") && line.find(" import ") != std::string_view::npos)) {
      return true;
    }
    if (!starts_with(line, "def ")) return false;
    const size_t open = line.find('(');
    const size_t close = line.rfind(')');
    return open != std::string_view::npos && close != std::string_view::npos && open < close &&
           line.substr(close + 1).find(':') != std::string_view::npos;
  };
  if (python_line(first)) return "Python";
  // Arduino sketches: "void setup(" / "void loop(" on a line of their own.
  size_t line_begin = 0;
  while (line_begin < code.size()) {
    size_t line_end = code.find('\n', line_begin);
    if (line_end == std::string_view::npos) line_end = code.size();
    std::string_view line = code.substr(line_begin, line_end - line_begin);
    line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t")));
    if (starts_with(line, "void setup(") || starts_with(line, "void loop(")) return "C/C++";
    line_begin = line_end + 1;
  }
  return {};
}

struct TextPiece {
  uint32_t offset;
  std::string_view raw;
  bool escaped;
  int group;  // pieces of different elements (<xhtml:p>s) are separated by a line end
};

class PlcOpenReader {
 public:
  explicit PlcOpenReader(std::string_view text) : text_(text) {}

  ContainerDocument read() {
    pugi::xml_document xml;
    if (auto problem = load_container_xml(xml, text_)) issues_.push_back(std::move(*problem));

    const pugi::xml_node root = xml.document_element();
    if (root && local_name(root) != "project") {
      issue(offset_of(root),
            fmt::format("not a PLCopen XML project: the root element is <{}>, not <project>", root.name()));
    } else if (root) {
      read_project(root);
    }
    ContainerDocument doc = builder_.finish(ContainerKind::PlcOpen);
    doc.issues = std::move(issues_);
    doc.objects = std::move(objects_);
    return doc;
  }

 private:
  // ---------------------------------------------------------------------------
  // Project structure
  // ---------------------------------------------------------------------------

  void read_project(pugi::xml_node project) {
    const pugi::xml_node types = child(project, "types");
    collect_data_types(project);
    for (const pugi::xml_node type : children(child(types, "dataTypes"), "dataType")) read_data_type(type);
    for (const pugi::xml_node pou : children(child(types, "pous"), "pou")) read_pou(pou);
    // CODESYS exports with a device: POUs and types inside the application's addData.
    const pugi::xml_node instances = child(project, "instances");
    read_embedded(instances);
    read_embedded(child(project, "addData"));
    for (const pugi::xml_node configuration : children(child(instances, "configurations"), "configuration")) {
      read_configuration(configuration);
    }
    // CODESYS exports of an application without its device: the application's
    // resource (tasks, GVLs, POUs) stands in the project's addData.
    for (const pugi::xml_node data : codesys_data_of(project, "application")) {
      for (const pugi::xml_node resource : children(data, "resource")) read_application(resource);
    }
  }

  // Every dataType of the file by lower-case name, so that a variable of a
  // derived type can be resolved (to quote a string's initial value).
  void collect_data_types(pugi::xml_node node) {
    for (const pugi::xml_node c : node.children()) {
      if (c.type() != pugi::node_element) continue;
      const std::string_view name = local_name(c);
      if (name == "dataType") {
        data_types_.emplace(lower(attribute(c, "name")), c);
      } else if (name != "pou" && name != "body" && name != "interface") {
        collect_data_types(c);
      }
    }
  }

  // Follows derived type names to the type they stand for (at most a few levels).
  pugi::xml_node resolve(pugi::xml_node type) const {
    for (int depth = 0; depth < 16 && local_name(type) == "derived"; ++depth) {
      const auto found = data_types_.find(lower(unescape_xml(type.attribute("name").value())));
      if (found == data_types_.end()) return {};
      type = first_element(child(found->second, "baseType"));
    }
    return type;
  }

  void read_embedded(pugi::xml_node node) {
    for (const pugi::xml_node c : node.children()) {
      if (c.type() != pugi::node_element) continue;
      const std::string_view name = local_name(c);
      if (name == "data") {
        const std::string_view kind = c.attribute("name").value();
        if (ends_with(kind, "/interface")) {
          for (const pugi::xml_node interface : children(c, "Interface")) read_interface(interface);
          continue;
        }
        if (ends_with(kind, "/pou")) {
          for (const pugi::xml_node pou : children(c, "pou")) read_pou(pou);
          continue;
        }
        if (ends_with(kind, "/datatype")) {
          for (const pugi::xml_node type : children(c, "dataType")) read_data_type(type);
          continue;
        }
      }
      if (name == "pou" || name == "interface" || name == "body") continue;
      read_embedded(c);
    }
  }

  // ---------------------------------------------------------------------------
  // Data types
  // ---------------------------------------------------------------------------

  void read_data_type(pugi::xml_node type) {
    begin_object(attribute(type, "name"), "declaration");
    ContainerObject object = make_object(type, "TYPE");
    line_start();
    syn("TYPE ");
    attr(type, "name");
    syn(" : ");
    const pugi::xml_node base = first_element(child(type, "baseType"));
    const std::string_view kind = local_name(base);
    if (kind == "struct") {
      syn("STRUCT\n");
      for (const pugi::xml_node member : children(base, "variable")) declaration(member, "  ");
      syn("END_STRUCT");
    } else if (kind == "enum") {
      enum_type(base);
    } else {
      type_spec(base);
    }
    if (const pugi::xml_node init = child(type, "initialValue")) {
      syn(" := ");
      value(init, base);
    }
    syn("; END_TYPE\n");
    objects_.push_back(std::move(object));
  }

  void enum_type(pugi::xml_node node) {
    if (const pugi::xml_node base = first_element(child(node, "baseType"))) {
      type_spec(base);
      syn(" ");
    }
    syn("(");
    bool first = true;
    for (const pugi::xml_node v : children(child(node, "values"), "value")) {
      if (!first) syn(", ");
      first = false;
      attr(v, "name");
      if (v.attribute("value")) {
        syn(" := ");
        attr(v, "value");
      }
    }
    syn(")");
  }

  // A type as it appears after ':' in a declaration. `node` is the type element
  // itself (<INT/>, <derived/>, <array>...).
  void type_spec(pugi::xml_node node) {
    const std::string_view kind = local_name(node);
    if (!node) {
      syn("ANY");  // a missing type: keeps the declaration readable
    } else if (kind == "derived") {
      attr(node, "name");
    } else if (kind == "string" || kind == "wstring") {
      syn(kind == "string" ? "STRING" : "WSTRING");
      if (node.attribute("length")) {
        syn("(");
        attr(node, "length");
        syn(")");
      }
    } else if (kind == "array") {
      syn("ARRAY [");
      bool first = true;
      for (const pugi::xml_node dimension : children(node, "dimension")) {
        if (!first) syn(", ");
        first = false;
        attr(dimension, "lower");
        syn("..");
        attr(dimension, "upper");
      }
      syn("] OF ");
      type_spec(first_element(child(node, "baseType")));
    } else if (kind == "pointer") {
      syn("POINTER TO ");
      type_spec(first_element(child(node, "baseType")));
    } else if (kind == "subrangeSigned" || kind == "subrangeUnsigned") {
      type_spec(first_element(child(node, "baseType")));
      const pugi::xml_node range = child(node, "range");
      syn(" (");
      attr(range, "lower");
      syn("..");
      attr(range, "upper");
      syn(")");
    } else if (kind == "struct") {
      syn("STRUCT\n");
      for (const pugi::xml_node member : children(node, "variable")) declaration(member, "    ");
      syn("  END_STRUCT");
    } else if (kind == "enum") {
      enum_type(node);
    } else {
      // Elementary types (<INT/>, <TIME/>, <LTIME/>...) are named by their tag.
      syn(kind);
    }
  }

  // An initial value; `node` holds <simpleValue>, <arrayValue> or <structValue>,
  // `type` is the type element of what it initialises (none when unknown).
  void value(pugi::xml_node node, pugi::xml_node type) {
    const pugi::xml_node v = first_element(node);
    const std::string_view kind = local_name(v);
    type = resolve(type);
    const std::string_view type_kind = local_name(type);
    if (kind == "simpleValue") {
      if (type_kind == "string" || type_kind == "wstring") {
        string_value(v, type_kind == "string" ? '\'' : '"');
      } else {
        attr(v, "value");
      }
    } else if (kind == "arrayValue") {
      const pugi::xml_node element_type =
          type_kind == "array" ? first_element(child(type, "baseType")) : pugi::xml_node();
      syn("[");
      bool first = true;
      for (const pugi::xml_node element : children(v, "value")) {
        if (!first) syn(", ");
        first = false;
        if (element.attribute("repetitionValue")) {
          attr(element, "repetitionValue");
          syn("(");
          value(element, element_type);
          syn(")");
        } else {
          value(element, element_type);
        }
      }
      syn("]");
    } else if (kind == "structValue") {
      syn("(");
      bool first = true;
      for (const pugi::xml_node element : children(v, "value")) {
        if (!first) syn(", ");
        first = false;
        attr(element, "member");
        syn(" := ");
        value(element, member_type(type, element.attribute("member").value()));
      }
      syn(")");
    } else {
      syn("0");
    }
  }

  // The type of a member of a struct type (none when `type` is no struct or lacks it).
  static pugi::xml_node member_type(pugi::xml_node type, std::string_view member) {
    if (local_name(type) != "struct") return {};
    const std::string wanted = lower(unescape_xml(member));
    for (const pugi::xml_node variable : children(type, "variable")) {
      if (lower(unescape_xml(variable.attribute("name").value())) == wanted) {
        return first_element(child(variable, "type"));
      }
    }
    return {};
  }

  // A string's initial value. Beremiz writes it without quotes (value="test");
  // rung adds them (synthetic) and escapes the quote and '$' with a synthetic '$', keeping
  // each character of the value mapped to the attribute. A value that is already
  // a quoted literal stands as it is.
  void string_value(pugi::xml_node simple, char quote) {
    const std::string unescaped = unescape_xml(simple.attribute("value").value());
    const size_t first = unescaped.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && (unescaped[first] == '\'' || unescaped[first] == '"')) {
      attr(simple, "value");
      return;
    }
    syn(std::string(1, quote));
    const auto located = locate_attribute(simple, "value");
    if (!located) {
      std::string escaped;
      for (const char c : unescaped) {
        if (c == quote || c == '$') escaped += '$';
        escaped += c;
      }
      syn(escaped);
    } else {
      const auto [offset, raw] = *located;
      // Walks the raw value: each character (or entity) that needs a '$' gets one.
      size_t run = 0;
      size_t i = 0;
      while (i < raw.size()) {
        size_t next = i + 1;
        char c = raw[i];
        if (c == '&') {
          const size_t semicolon = raw.find(';', i);
          if (semicolon != std::string_view::npos) {
            const std::string replacement = unescape_xml(raw.substr(i, semicolon + 1 - i));
            if (replacement.size() == 1) {
              c = replacement[0];
              next = semicolon + 1;
            }
          }
        }
        if (c == quote || c == '$') {
          if (i > run)
            append_escaped_text(builder_, raw.substr(run, i - run), offset + static_cast<uint32_t>(run), role_, owner_);
          syn("$");
          append_escaped_text(builder_, raw.substr(i, next - i), offset + static_cast<uint32_t>(i), role_, owner_);
          run = next;
        }
        i = next;
      }
      if (raw.size() > run) {
        append_escaped_text(builder_, raw.substr(run), offset + static_cast<uint32_t>(run), role_, owner_);
      }
    }
    syn(std::string(1, quote));
  }

  // `name AT address : type := value;` for one <variable>.
  void declaration(pugi::xml_node variable, std::string_view indent) {
    const std::string name = attribute(variable, "name");
    if (!is_identifier(name)) {
      const auto located = locate_attribute(variable, "name");
      issue(located ? located->first : offset_of(variable),
            fmt::format("variable name '{}' is not an IEC identifier; the variable is left out", name));
      return;
    }
    syn(indent);
    attr(variable, "name");
    if (variable.attribute("address")) {
      syn(" AT ");
      attr(variable, "address");
    }
    syn(" : ");
    const pugi::xml_node type = first_element(child(variable, "type"));
    type_spec(type);
    if (const pugi::xml_node init = child(variable, "initialValue")) {
      syn(" := ");
      value(init, type);
    }
    syn(";\n");
  }

  // ---------------------------------------------------------------------------
  // POUs
  // ---------------------------------------------------------------------------

  void read_pou(pugi::xml_node pou) {
    const std::string name = attribute(pou, "name");
    const std::string_view pou_type = pou.attribute("pouType").value();
    std::string keyword;
    if (pou_type == "program") {
      keyword = "PROGRAM";
    } else if (pou_type == "function") {
      keyword = "FUNCTION";
    } else if (pou_type == "functionBlock") {
      keyword = "FUNCTION_BLOCK";
    } else {
      ContainerObject object = make_object(pou, pou_type.empty() ? "POU" : std::string(pou_type));
      object.name = name;
      object.note = fmt::format("pouType \"{}\" is not a program, function or function block; skipped", pou_type);
      objects_.push_back(std::move(object));
      return;
    }
    begin_object(name, "declaration");
    ContainerObject main = make_object(pou, keyword);

    line_start();
    if (!plain_text_interface(pou, "declaration")) {
      syn(keyword + " ");
      attr(pou, "name");
      if (keyword == "FUNCTION") {
        if (const pugi::xml_node type = first_element(child(child(pou, "interface"), "returnType"))) {
          syn(" : ");
          type_spec(type);
        }
      }
      if (keyword == "FUNCTION_BLOCK") inheritance(pou);
      syn("\n");
      var_blocks(child(pou, "interface"));
    }
    body(pou, "implementation", main);
    objects_.push_back(std::move(main));

    for (const pugi::xml_node data : codesys_data_of(pou, "method")) {
      for (const pugi::xml_node method : children(data, "Method")) read_method(method);
    }
    for (const pugi::xml_node data : codesys_data_of(pou, "property")) {
      for (const pugi::xml_node property : children(data, "Property")) read_property(property);
    }
    for (const pugi::xml_node action : children(child(pou, "actions"), "action")) {
      read_sub(action, "ACTION", "END_ACTION", "action ");
    }
    for (const pugi::xml_node transition : children(child(pou, "transitions"), "transition")) {
      read_sub(transition, "TRANSITION", "END_TRANSITION", "transition ");
    }
    role_ = "end";
    line_start();
    syn("END_" + keyword + "\n");
  }

  // EXTENDS/IMPLEMENTS from CODESYS' pouinheritance data (in the interface or the POU).
  void inheritance(pugi::xml_node pou) {
    std::vector<pugi::xml_node> data = codesys_data_of(child(pou, "interface"), "pouinheritance");
    for (const pugi::xml_node d : codesys_data_of(pou, "pouinheritance")) data.push_back(d);
    for (const pugi::xml_node d : data) {
      const pugi::xml_node inheritance = child(d, "Inheritance");
      for (const auto& [tag, keyword] : {std::pair{"Extends", " EXTENDS "}, std::pair{"Implements", " IMPLEMENTS "}}) {
        bool first = true;
        for (const pugi::xml_node name : children(inheritance, tag)) {
          syn(first ? keyword : ", ");
          first = false;
          element_text(name);
        }
      }
    }
  }

  void var_blocks(pugi::xml_node interface) {
    for (const pugi::xml_node list : interface.children()) {
      if (list.type() != pugi::node_element) continue;
      const std::string_view kind = local_name(list);
      std::string_view keyword;
      if (kind == "inputVars")
        keyword = "VAR_INPUT";
      else if (kind == "outputVars")
        keyword = "VAR_OUTPUT";
      else if (kind == "inOutVars")
        keyword = "VAR_IN_OUT";
      else if (kind == "localVars")
        keyword = "VAR";
      else if (kind == "tempVars")
        keyword = "VAR_TEMP";
      else if (kind == "externalVars")
        keyword = "VAR_EXTERNAL";
      else if (kind == "globalVars")
        keyword = "VAR_GLOBAL";
      else
        continue;  // returnType, addData, documentation; accessVars have no <variable>s
      var_block(list, keyword);
    }
  }

  void var_block(pugi::xml_node list, std::string_view keyword) {
    line_start();
    syn(keyword);
    if (is_true(list, "constant")) syn(" CONSTANT");
    if (is_true(list, "retain")) syn(" RETAIN");
    if (is_true(list, "nonretain")) syn(" NON_RETAIN");
    if (is_true(list, "persistent")) syn(" PERSISTENT");
    syn("\n");
    for (const pugi::xml_node variable : children(list, "variable")) declaration(variable, "  ");
    syn("END_VAR\n");
  }

  // The declaration CODESYS stored as text (InterfaceAsPlainText), as real text;
  // false when there is none.
  bool plain_text_interface(pugi::xml_node owner, const std::string& role) {
    pugi::xml_node plain = child(owner, "InterfaceAsPlainText");
    for (const pugi::xml_node holder : {owner, child(owner, "interface")}) {
      for (const pugi::xml_node data : codesys_data_of(holder, "interfaceasplaintext")) {
        if (!plain) plain = child(data, "InterfaceAsPlainText");
      }
    }
    if (!plain) return false;
    const std::vector<TextPiece> pieces = text_pieces(plain);
    if (!has_code(pieces)) return false;
    role_ = role;
    line_start();
    add_pieces(pieces);
    line_start();
    return true;
  }

  // The body of a POU, method or accessor: textual bodies become real text,
  // graphical ones are noted on the object.
  void body(pugi::xml_node owner, const std::string& role, ContainerObject& object) {
    const pugi::xml_node b = child(owner, "body");
    if (!b) return;
    const pugi::xml_node language = body_language(b);
    if (!language) return;
    const std::string_view name = local_name(language);
    if (object.language.empty()) object.language = std::string(name);
    if (name == "ST" || name == "IL") {
      const std::vector<TextPiece> pieces = text_pieces(language);
      if (!has_code(pieces)) return;
      if (const std::string_view foreign = foreign_language(joined_text(pieces)); !foreign.empty()) {
        if (object.note.empty()) {
          object.note = fmt::format("{} body holds {} code, not {}; not read as text", name, foreign, name);
        }
        return;
      }
      role_ = role;
      line_start();
      add_pieces(pieces);
      line_start();
    } else if (object.note.empty()) {
      object.note = fmt::format("{} implementation is graphical; not read as text", name);
    }
  }

  // <ST>, <IL>, <FBD>, <LD>, <SFC>, or a CODESYS CFC body inside <addData>.
  static pugi::xml_node body_language(pugi::xml_node body) {
    for (const pugi::xml_node c : body.children()) {
      if (c.type() != pugi::node_element) continue;
      const std::string_view name = local_name(c);
      if (name == "documentation") continue;
      if (name != "addData") return c;
      for (const pugi::xml_node data : children(c, "data")) {
        if (const pugi::xml_node inner = first_element(data)) return inner;
      }
    }
    return {};
  }

  void read_method(pugi::xml_node method) {
    const std::string name = attribute(method, "name");
    const std::string prefix = "method " + name;
    ContainerObject object = make_object(method, "METHOD");
    object.name = owner_ + "." + name;
    if (!plain_text_interface(method, prefix + "/declaration")) {
      role_ = prefix + "/declaration";
      line_start();
      syn("METHOD ");
      access_modifiers(method);
      attr(method, "name");
      if (const pugi::xml_node type = first_element(child(child(method, "interface"), "returnType"))) {
        syn(" : ");
        type_spec(type);
      }
      syn("\n");
      var_blocks(child(method, "interface"));
    }
    body(method, prefix + "/implementation", object);
    role_ = prefix + "/declaration";
    line_start();
    syn("END_METHOD\n");
    objects_.push_back(std::move(object));
  }

  // A CODESYS interface (project addData .../interface): INTERFACE with its
  // methods and properties, which have declarations only.
  void read_interface(pugi::xml_node interface) {
    begin_object(attribute(interface, "name"), "declaration");
    ContainerObject object = make_object(interface, "INTERFACE");
    line_start();
    if (!plain_text_interface(interface, "declaration")) {
      syn("INTERFACE ");
      attr(interface, "name");
      bool first = true;
      for (const pugi::xml_node data : children(child(interface, "addData"), "data")) {
        for (const pugi::xml_node name : children(child(data, "Inheritance"), "Extends")) {
          syn(first ? " EXTENDS " : ", ");
          first = false;
          element_text(name);
        }
      }
      syn("\n");
    }
    objects_.push_back(std::move(object));
    for (const pugi::xml_node method : children(child(interface, "Methods"), "Method")) read_method(method);
    for (const pugi::xml_node property : children(child(interface, "Properties"), "Property")) {
      read_property(property);
    }
    role_ = "end";
    line_start();
    syn("END_INTERFACE\n");
  }

  void access_modifiers(pugi::xml_node member) {
    for (const pugi::xml_node data : codesys_data_of(child(member, "interface"), "accessmodifiers")) {
      const pugi::xml_node modifiers = child(data, "AccessModifiers");
      for (const auto& [attribute_name, keyword] :
           {std::pair{"Private", "PRIVATE "}, std::pair{"Protected", "PROTECTED "}, std::pair{"Internal", "INTERNAL "},
            std::pair{"Public", "PUBLIC "}}) {
        if (is_true(modifiers, attribute_name)) syn(keyword);
      }
    }
  }

  void read_property(pugi::xml_node property) {
    const std::string name = attribute(property, "name");
    const std::string prefix = "property " + name;
    ContainerObject object = make_object(property, "PROPERTY");
    object.name = owner_ + "." + name;
    if (!plain_text_interface(property, prefix + "/declaration")) {
      role_ = prefix + "/declaration";
      line_start();
      syn("PROPERTY ");
      access_modifiers(property);
      attr(property, "name");
      if (const pugi::xml_node type = first_element(child(child(property, "interface"), "returnType"))) {
        syn(" : ");
        type_spec(type);
      }
      syn("\n");
    }
    for (const auto& [tag, keyword, suffix] :
         {std::tuple{"GetAccessor", "GET", "/get"}, std::tuple{"SetAccessor", "SET", "/set"}}) {
      const pugi::xml_node accessor = child(property, tag);
      if (!accessor) continue;
      const std::string role = prefix + suffix;
      role_ = role;
      line_start();
      syn(std::string(keyword) + "\n");
      if (!plain_text_interface(accessor, role + "/declaration")) {
        role_ = role;
        var_blocks(child(accessor, "interface"));
      }
      body(accessor, role + "/implementation", object);
      role_ = role;
      line_start();
      syn(fmt::format("END_{}\n", keyword));
    }
    role_ = prefix + "/declaration";
    line_start();
    syn("END_PROPERTY\n");
    objects_.push_back(std::move(object));
  }

  // An action or transition: `ACTION name:` + body + `END_ACTION` when the body is
  // text; graphical or empty ones are only listed.
  void read_sub(pugi::xml_node sub, const char* keyword, const char* end, const char* role_prefix) {
    const std::string name = attribute(sub, "name");
    ContainerObject object = make_object(sub, keyword);
    object.name = owner_ + "." + name;
    const std::string role = role_prefix + name;
    const pugi::xml_node language = body_language(child(sub, "body"));
    const std::string_view lang = language ? local_name(language) : std::string_view();
    object.language = std::string(lang);
    const bool textual = lang == "ST" || lang == "IL";
    std::vector<TextPiece> pieces = textual ? text_pieces(language) : std::vector<TextPiece>();
    if (textual && has_code(pieces)) {
      role_ = role;
      line_start();
      syn(fmt::format("{} ", keyword));
      attr(sub, "name");
      syn(":\n");
      // Beremiz writes an ST transition as ":= expression;" (its generator puts
      // it after "TRANSITION FROM a TO b"). The ':=' is left out of the virtual
      // text, so that "TRANSITION name:" + the expression is what the grammar reads.
      if (std::string_view(keyword) == "TRANSITION" && lang == "ST" && drop_leading_assign(pieces)) {
        line_start();
        add_pieces(pieces);
        line_start();
      } else {
        body(sub, role, object);
      }
      role_ = role;
      line_start();
      syn(fmt::format("{}\n", end));
    } else if (language && !textual) {
      object.note = fmt::format("{} implementation is graphical; not read as text", lang);
    } else {
      object.note = "empty; not in the virtual text";
    }
    objects_.push_back(std::move(object));
  }

  // ---------------------------------------------------------------------------
  // Configurations
  // ---------------------------------------------------------------------------

  void read_configuration(pugi::xml_node configuration) {
    begin_object(attribute(configuration, "name"), "configuration");
    objects_.push_back(make_object(configuration, "CONFIGURATION"));
    line_start();
    syn("CONFIGURATION ");
    attr(configuration, "name");
    syn("\n");
    for (const pugi::xml_node globals : children(configuration, "globalVars")) var_block(globals, "VAR_GLOBAL");
    for (const pugi::xml_node resource : children(configuration, "resource")) read_resource(resource);
    syn("END_CONFIGURATION\n");
  }

  // A CODESYS application resource from the project's addData: a configuration
  // of its own, named (synthetically) after the resource, whose name attribute
  // is mapped on the RESOURCE line.
  void read_application(pugi::xml_node resource) {
    const std::string name = attribute(resource, "name");
    begin_object(name, "configuration");
    objects_.push_back(make_object(resource, "CONFIGURATION"));
    line_start();
    syn("CONFIGURATION " + name + "\n");
    read_resource(resource);
    syn("END_CONFIGURATION\n");
  }

  void read_resource(pugi::xml_node resource) {
    syn("RESOURCE ");
    attr(resource, "name");
    syn(" ON PLC\n");
    for (const pugi::xml_node globals : children(resource, "globalVars")) var_block(globals, "VAR_GLOBAL");
    for (const pugi::xml_node task : children(resource, "task")) {
      syn("  TASK ");
      attr(task, "name");
      std::vector<std::pair<const char*, const char*>> arguments;
      if (task.attribute("single")) arguments.emplace_back("SINGLE", "single");
      if (task.attribute("interval")) arguments.emplace_back("INTERVAL", "interval");
      if (task.attribute("priority")) arguments.emplace_back("PRIORITY", "priority");
      if (!arguments.empty()) {
        syn("(");
        bool first = true;
        for (const auto& [parameter, attribute_name] : arguments) {
          if (!first) syn(", ");
          first = false;
          syn(fmt::format("{} := ", parameter));
          if (std::string_view(attribute_name) == "interval") {
            interval(task);
          } else {
            attr(task, attribute_name);
          }
        }
        syn(")");
      }
      syn(";\n");
    }
    for (const pugi::xml_node task : children(resource, "task")) {
      for (const pugi::xml_node instance : children(task, "pouInstance")) program_instance(instance, task);
    }
    for (const pugi::xml_node instance : children(resource, "pouInstance")) program_instance(instance, {});
    syn("END_RESOURCE\n");
  }

  void interval(pugi::xml_node task) {
    const std::string value = attribute(task, "interval");
    const std::string converted = iec_interval(value);
    if (converted == value) {
      attr(task, "interval");
    } else {
      syn(converted);
    }
  }

  void program_instance(pugi::xml_node instance, pugi::xml_node task) {
    syn("  PROGRAM ");
    attr(instance, "name");
    if (task) {
      // Synthetic: the task's name attribute is already mapped to its TASK line.
      syn(" WITH ");
      syn(attribute(task, "name"));
    }
    syn(" : ");
    // CODESYS writes typeName="" for a program called by its own name.
    if (is_blank(instance.attribute("typeName").value())) {
      syn(attribute(instance, "name"));
    } else {
      attr(instance, "typeName");
    }
    syn(";\n");
  }

  // ---------------------------------------------------------------------------
  // Text pieces
  // ---------------------------------------------------------------------------

  // The character data of a formattedText element: the text of its XHTML
  // children (<xhtml:p>, CODESYS <xhtml>), or its own text when it has none.
  std::vector<TextPiece> text_pieces(pugi::xml_node element) {
    std::vector<TextPiece> pieces;
    int group = 0;
    bool has_elements = false;
    for (const pugi::xml_node c : element.children()) {
      if (c.type() != pugi::node_element) continue;
      has_elements = true;
      collect_text(c, group++, pieces);
    }
    if (!has_elements) collect_text(element, group, pieces);
    return pieces;
  }

  void collect_text(pugi::xml_node element, int group, std::vector<TextPiece>& pieces) {
    for (const pugi::xml_node node : element.children()) {
      const bool cdata = node.type() == pugi::node_cdata;
      if (!cdata && node.type() != pugi::node_pcdata) continue;
      const std::string_view value = node.value();
      if (value.empty()) continue;
      const ptrdiff_t at = node.offset_debug();
      const bool located = at >= 0 && static_cast<size_t>(at) + value.size() <= text_.size() &&
                           text_.substr(static_cast<size_t>(at), value.size()) == value;
      if (!located) {
        issue(0, fmt::format("could not locate the text of <{}> in the file; positions in it are approximate",
                             element.name()));
        continue;
      }
      pieces.push_back({static_cast<uint32_t>(at), value, !cdata, group});
    }
  }

  // Removes a leading ':=' (after blanks and comments) from the first piece that
  // holds code, splitting it; false when the code does not start with ':='.
  static bool drop_leading_assign(std::vector<TextPiece>& pieces) {
    for (size_t k = 0; k < pieces.size(); ++k) {
      TextPiece& piece = pieces[k];
      const size_t at = skip_blanks_and_comments(piece.raw, 0);
      if (at >= piece.raw.size()) continue;  // only blanks or comments: look in the next piece
      if (piece.raw.compare(at, 2, ":=") != 0) return false;
      TextPiece after = piece;
      after.offset = piece.offset + static_cast<uint32_t>(at + 2);
      after.raw = piece.raw.substr(at + 2);
      piece.raw = piece.raw.substr(0, at);
      pieces.insert(pieces.begin() + static_cast<ptrdiff_t>(k) + 1, after);
      std::erase_if(pieces, [](const TextPiece& p) { return p.raw.empty(); });
      return true;
    }
    return false;
  }

  // The unescaped text of the pieces, a line end between elements (no positions).
  static std::string joined_text(const std::vector<TextPiece>& pieces) {
    std::string out;
    int group = pieces.empty() ? 0 : pieces.front().group;
    for (const TextPiece& piece : pieces) {
      if (piece.group != group) out += '\n';
      group = piece.group;
      out += piece.escaped ? unescape_xml(piece.raw) : std::string(piece.raw);
    }
    return out;
  }

  static bool has_code(const std::vector<TextPiece>& pieces) {
    return std::any_of(pieces.begin(), pieces.end(), [](const TextPiece& p) { return !is_blank(p.raw); });
  }

  void add_pieces(const std::vector<TextPiece>& pieces) {
    int group = pieces.empty() ? 0 : pieces.front().group;
    for (const TextPiece& piece : pieces) {
      if (piece.group != group) {
        line_start();
        group = piece.group;
      }
      if (piece.escaped) {
        append_escaped_text(builder_, piece.raw, piece.offset, role_, owner_);
      } else {
        builder_.append_real(piece.raw, piece.offset, role_, owner_);
      }
      last_char_ = piece.raw.back();
    }
  }

  // The text of a small element (<Extends>Base</Extends>) as real text.
  void element_text(pugi::xml_node element) {
    for (const TextPiece& piece : text_pieces(element)) {
      const size_t begin = piece.raw.find_first_not_of(" \t\r\n");
      if (begin == std::string_view::npos) continue;
      const size_t end = piece.raw.find_last_not_of(" \t\r\n") + 1;
      const std::string_view raw = piece.raw.substr(begin, end - begin);
      const uint32_t offset = piece.offset + static_cast<uint32_t>(begin);
      if (piece.escaped) {
        append_escaped_text(builder_, raw, offset, role_, owner_);
      } else {
        builder_.append_real(raw, offset, role_, owner_);
      }
      last_char_ = raw.back();
    }
  }

  // ---------------------------------------------------------------------------
  // Emitting
  // ---------------------------------------------------------------------------

  void begin_object(std::string name, std::string role) {
    owner_ = std::move(name);
    role_ = std::move(role);
  }

  ContainerObject make_object(pugi::xml_node element, std::string kind) const {
    ContainerObject object;
    object.name = owner_;
    object.kind = std::move(kind);
    object.file_offset = offset_of(element);
    return object;
  }

  void syn(std::string_view s) {
    if (s.empty()) return;
    builder_.append_synthetic(s, role_, owner_);
    last_char_ = s.back();
  }

  // Starts a new line unless the text already ends with one.
  void line_start() {
    if (!builder_.empty() && last_char_ != '\n') {
      builder_.append_synthetic("\n", "separator", owner_);
      last_char_ = '\n';
    }
  }

  // An attribute's value: real text on the value in the file (entities
  // unescaped piece by piece), or synthetic when it cannot be located.
  void attr(pugi::xml_node element, const char* name) {
    const pugi::xml_attribute a = element.attribute(name);
    if (!a) return;
    if (const auto located = locate_attribute(element, name)) {
      if (located->second.empty()) return;
      append_escaped_text(builder_, located->second, located->first, role_, owner_);
      last_char_ = unescape_xml(located->second).back();
      return;
    }
    syn(unescape_xml(a.value()));
  }

  // The file offset and raw text of an attribute value, found by reading the
  // element's start tag (pugixml keeps no offsets for attributes).
  std::optional<std::pair<uint32_t, std::string_view>> locate_attribute(pugi::xml_node element,
                                                                        std::string_view name) const {
    const ptrdiff_t at = element.offset_debug();
    if (at <= 0 || static_cast<size_t>(at) > text_.size() || text_[static_cast<size_t>(at) - 1] != '<') {
      return std::nullopt;
    }
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    size_t i = static_cast<size_t>(at);
    while (i < text_.size() && !space(text_[i]) && text_[i] != '>' && text_[i] != '/') ++i;
    while (i < text_.size()) {
      while (i < text_.size() && space(text_[i])) ++i;
      if (i >= text_.size() || text_[i] == '>' || text_[i] == '/') return std::nullopt;
      const size_t name_begin = i;
      while (i < text_.size() && !space(text_[i]) && text_[i] != '=' && text_[i] != '>') ++i;
      const std::string_view attribute_name = text_.substr(name_begin, i - name_begin);
      while (i < text_.size() && space(text_[i])) ++i;
      if (i >= text_.size() || text_[i] != '=') return std::nullopt;
      ++i;
      while (i < text_.size() && space(text_[i])) ++i;
      if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) return std::nullopt;
      const char quote = text_[i++];
      const size_t close = text_.find(quote, i);
      if (close == std::string_view::npos) return std::nullopt;
      if (attribute_name == name) return std::pair{static_cast<uint32_t>(i), text_.substr(i, close - i)};
      i = close + 1;
    }
    return std::nullopt;
  }

  std::string attribute(pugi::xml_node element, const char* name) const {
    return unescape_xml(element.attribute(name).value());
  }

  uint32_t offset_of(pugi::xml_node element) const {
    // offset_debug() of an element is its name; the element starts at the '<' before it.
    const ptrdiff_t at = element.offset_debug();
    if (at <= 0) return 0;
    return static_cast<uint32_t>(std::min<size_t>(static_cast<size_t>(at - 1), text_.size()));
  }

  void issue(uint32_t offset, std::string message) { issues_.push_back({offset, std::move(message)}); }

  std::string_view text_;
  std::unordered_map<std::string, pugi::xml_node> data_types_;
  VirtualTextBuilder builder_;
  std::string owner_;
  std::string role_;
  char last_char_ = '\n';
  std::vector<ContainerIssue> issues_;
  std::vector<ContainerObject> objects_;
};

}  // namespace

ContainerDocument read_plcopen(std::string_view text) {
  return PlcOpenReader(text).read();
}

bool looks_like_plcopen(std::string_view text) {
  const std::string_view head = text.substr(0, 8192);
  // The root element: the first tag that is not a declaration, comment or doctype
  // (a comment may hold tags: "<!-- see the <addData> block -->").
  size_t at = 0;
  while ((at = head.find('<', at)) != std::string_view::npos) {
    const size_t skipped = skip_special_markup(head, at);
    if (skipped == std::string_view::npos) break;
    at = skipped;
  }
  if (at == std::string_view::npos) return false;
  size_t end = at + 1;
  while (end < head.size() && !std::isspace(static_cast<unsigned char>(head[end])) && head[end] != '>' &&
         head[end] != '/') {
    ++end;
  }
  std::string_view root = head.substr(at + 1, end - at - 1);
  if (const size_t colon = root.find(':'); colon != std::string_view::npos) root = root.substr(colon + 1);
  if (root != "project") return false;
  return head.find("www.plcopen.org/xml/tc6_0201", at) != std::string_view::npos ||
         head.find("www.plcopen.org/xml/tc6_0200", at) != std::string_view::npos;
}

}  // namespace rung::containers
