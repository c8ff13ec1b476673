#include "vcs/merge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <utility>

#include "formatter/unified_diff.hpp"
#include "parser/ast.hpp"
#include "parser/containers/read_container.hpp"
#include "parser/keywords.hpp"
#include "parser/source/decode.hpp"
#include "parser/source/encode.hpp"
#include "parser/syntax_tree.hpp"

namespace rung::vcs {
namespace {

using Lines = std::vector<std::string_view>;

void ensure_line_end(std::string& out, std::string_view eol) {
  if (!out.empty() && out.back() != '\n') out += eol;
}

// The line end a text uses ("\r\n" when its first line ends so).
std::string_view line_end_of(std::string_view text) {
  const size_t nl = text.find('\n');
  return nl != std::string_view::npos && nl > 0 && text[nl - 1] == '\r' ? "\r\n" : "\n";
}

// One side's replacement of base lines [begin, end).
struct SideChange {
  size_t begin = 0;
  size_t end = 0;
  Lines lines;
  int side = 0;  // 0 ours, 1 theirs
};

void append_lines(std::string& out, const Lines& lines, size_t begin, size_t end) {
  for (size_t i = begin; i < end && i < lines.size(); ++i) out += lines[i];
}

// The text of base lines [begin, end) with one side's changes in that range applied.
std::string apply_side(const Lines& base, const std::vector<SideChange>& changes, size_t first, size_t last, int side,
                       size_t begin, size_t end) {
  std::string out;
  size_t at = begin;
  for (size_t i = first; i < last; ++i) {
    const SideChange& c = changes[i];
    if (c.side != side) continue;
    append_lines(out, base, at, c.begin);
    for (const std::string_view line : c.lines) out += line;
    at = c.end;
  }
  append_lines(out, base, at, end);
  return out;
}

void append_conflict(std::string& out, std::string_view ours, std::string_view theirs, const MergeLabels& labels,
                     std::string_view eol) {
  ensure_line_end(out, eol);
  out += fmt::format("<<<<<<< {}{}", labels.ours, eol);
  out += ours;
  ensure_line_end(out, eol);
  out += fmt::format("======={}", eol);
  out += theirs;
  ensure_line_end(out, eol);
  out += fmt::format(">>>>>>> {}{}", labels.theirs, eol);
}

// Keys of units in three versions, aligned: our order, with their additions after the unit
// that precedes them on their side.
struct Slot {
  int base = -1;
  int ours = -1;
  int theirs = -1;
};

std::vector<Slot> align(const std::vector<std::string>& base, const std::vector<std::string>& ours,
                        const std::vector<std::string>& theirs) {
  const auto index = [](const std::vector<std::string>& keys) {
    std::map<std::string, int> m;
    for (size_t i = 0; i < keys.size(); ++i) m.emplace(keys[i], static_cast<int>(i));
    return m;
  };
  const std::map<std::string, int> b = index(base);
  const std::map<std::string, int> t = index(theirs);
  const auto find = [](const std::map<std::string, int>& m, const std::string& key) {
    const auto it = m.find(key);
    return it == m.end() ? -1 : it->second;
  };
  std::vector<Slot> slots;
  std::vector<std::string> keys;
  for (size_t i = 0; i < ours.size(); ++i) {
    slots.push_back({find(b, ours[i]), static_cast<int>(i), find(t, ours[i])});
    keys.push_back(ours[i]);
  }
  for (size_t i = 0; i < theirs.size(); ++i) {
    if (std::find(keys.begin(), keys.end(), theirs[i]) != keys.end()) continue;
    size_t at = 0;
    for (size_t p = i; p-- > 0;) {
      const auto it = std::find(keys.begin(), keys.end(), theirs[p]);
      if (it != keys.end()) {
        at = static_cast<size_t>(it - keys.begin()) + 1;
        break;
      }
    }
    // After what we added there too: ours first.
    while (at < slots.size() && slots[at].base < 0 && slots[at].theirs < 0) ++at;
    slots.insert(slots.begin() + static_cast<std::ptrdiff_t>(at), Slot{find(b, theirs[i]), -1, static_cast<int>(i)});
    keys.insert(keys.begin() + static_cast<std::ptrdiff_t>(at), theirs[i]);
  }
  return slots;
}

bool has_duplicates(std::vector<std::string> keys) {
  std::sort(keys.begin(), keys.end());
  return std::adjacent_find(keys.begin(), keys.end()) != keys.end();
}

// ---- plain ST: top-level objects ----

struct Unit {
  std::string key;
  std::string text;
};

std::vector<std::string> unit_keys(const std::vector<Unit>& units) {
  std::vector<std::string> keys;
  keys.reserve(units.size());
  for (const Unit& u : units) keys.push_back(u.key);
  return keys;
}

void add_member_keys(const ast::Pou& pou, const std::string& prefix, SyntaxNode root,
                     std::map<uint32_t, std::string>& keys) {
  for (const ast::Pou& member : pou.members()) {
    std::string name(member.name());
    if (name.empty()) name = keywords::upper(member.node().child(0).text());
    const std::string key = prefix + "." + keywords::upper(name);
    if (member.node().parent() == root) keys.emplace(member.node().begin(), "member:" + key);
    add_member_keys(member, key, root, keys);
  }
}

std::optional<std::vector<Unit>> st_units(std::string_view text) {
  const SyntaxTree tree = SyntaxTree::parse(std::string(text));
  if (tree.aborted() || tree.root().has_error()) return std::nullopt;
  const SyntaxNode root = tree.root();
  const ast::Outline outline = ast::outline(root);
  std::map<uint32_t, std::string> keys;
  for (const ast::Pou& pou : outline.pous) {
    keys.emplace(pou.node().begin(), "pou:" + keywords::upper(pou.name()));
    add_member_keys(pou, keywords::upper(pou.name()), root, keys);
  }
  for (const ast::TypeDeclaration& type : outline.types) {
    SyntaxNode top = type.node();
    while (top.parent() && top.parent() != root) top = top.parent();
    keys.emplace(top.begin(), "type:" + keywords::upper(type.name()));
  }
  // A VAR_GLOBAL block is known by its section and qualifiers and its place among the blocks
  // that share them, not by its first variable: adding or renaming that variable on both sides
  // would otherwise make two new blocks out of one, each with a copy of the rest.
  std::map<std::string, int> gvl_count;
  for (const ast::VarBlock& block : outline.global_blocks) {
    std::string label(ast::var_section_name(block.section()));
    for (const std::string_view q : {"CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"}) {
      if (block.has_qualifier(q)) label += fmt::format(" {}", q);
    }
    keys.emplace(block.node().begin(), fmt::format("gvl:{}#{}", label, gvl_count[label]++));
  }
  for (const SyntaxNode& configuration : outline.configurations) {
    keys.emplace(configuration.begin(),
                 "configuration:" + keywords::upper(configuration.child_by_field("name").text()));
  }
  std::vector<Unit> units;
  uint32_t at = 0;
  bool unknown = false;
  root.for_each_child([&](SyntaxNode child) {
    if (unknown || child.is_extra()) return;
    const auto it = keys.find(child.begin());
    if (it == keys.end()) {
      unknown = true;
      return;
    }
    // The unit runs to the end of its last line.
    size_t end = child.end();
    const size_t nl = text.find('\n', end);
    if (nl != std::string_view::npos &&
        text.substr(end, nl - end).find_first_not_of(" \t\r") == std::string_view::npos) {
      end = nl + 1;
    }
    units.push_back({it->second, std::string(text.substr(at, end - at))});
    at = static_cast<uint32_t>(end);
  });
  if (unknown) return std::nullopt;
  units.push_back({"\x01tail", std::string(text.substr(at))});
  return units;
}

// The name in a unit key ("pou:FB_A" and "FUNCTION_BLOCK:/FOLDER/FB_A": "FB_A"; a member's
// "member:FB_A.M_RUN" and an .EXP action's "ACTION:/FOLDER/FB_A.RESET": "FB_A.M_RUN", "FB_A.RESET").
std::string_view unit_name(std::string_view key) {
  key.remove_prefix(std::min(key.size(), key.find(':') + 1));
  const size_t slash = key.rfind('/');
  return slash == std::string_view::npos ? key : key.substr(slash + 1);
}

// Merges units by key (see align); a unit changed on one side and deleted on the other is a
// conflict written with markers. So is the deletion of a POU one of whose members (a method or
// action written after it) is such a conflict: kept with the member, not taken from under it.
MergeResult merge_units(const std::vector<Unit>& base, const std::vector<Unit>& ours, const std::vector<Unit>& theirs,
                        const MergeLabels& labels) {
  MergeResult result;
  const std::vector<Slot> slots = align(unit_keys(base), unit_keys(ours), unit_keys(theirs));
  const auto unit = [](const std::vector<Unit>& units, int at) {
    return at >= 0 ? &units[static_cast<size_t>(at)] : nullptr;
  };
  const auto shown = [](const Unit* u) { return u->key.substr(u->key.find(':') + 1); };
  std::set<std::string, std::less<>> owners_in_conflict;
  for (const Slot& slot : slots) {
    const Unit* b = unit(base, slot.base);
    const Unit* kept = slot.theirs < 0 ? unit(ours, slot.ours) : slot.ours < 0 ? unit(theirs, slot.theirs) : nullptr;
    if (b == nullptr || kept == nullptr || kept->text == b->text) continue;
    const std::string_view name = unit_name(kept->key);
    if (name.find('.') != std::string_view::npos) owners_in_conflict.emplace(name.substr(0, name.find('.')));
  }
  for (const Slot& slot : slots) {
    const Unit* b = unit(base, slot.base);
    const Unit* o = unit(ours, slot.ours);
    const Unit* t = unit(theirs, slot.theirs);
    if (o != nullptr && t != nullptr) {
      MergeResult part = merge_lines(b != nullptr ? b->text : std::string(), o->text, t->text, labels);
      result.text += part.text;
      result.conflicts += part.conflicts;
    } else if (o != nullptr) {
      if (b == nullptr) {
        result.text += o->text;  // we added it
      } else if (b->text != o->text) {
        append_conflict(result.text, o->text, {}, labels, line_end_of(o->text));
        ++result.conflicts;
        result.notes.push_back(fmt::format("{}: changed on our side, deleted on theirs", shown(o)));
      } else if (owners_in_conflict.count(unit_name(o->key)) > 0) {
        append_conflict(result.text, o->text, {}, labels, line_end_of(o->text));
        ++result.conflicts;
        result.notes.push_back(fmt::format("{}: deleted on their side, a member of it changed on ours", shown(o)));
      }
    } else if (t != nullptr) {
      if (b == nullptr) {
        result.text += t->text;  // they added it
      } else if (b->text != t->text) {
        append_conflict(result.text, {}, t->text, labels, line_end_of(t->text));
        ++result.conflicts;
        result.notes.push_back(fmt::format("{}: deleted on our side, changed on theirs", shown(t)));
      } else if (owners_in_conflict.count(unit_name(t->key)) > 0) {
        append_conflict(result.text, {}, t->text, labels, line_end_of(t->text));
        ++result.conflicts;
        result.notes.push_back(fmt::format("{}: deleted on our side, a member of it changed on theirs", shown(t)));
      }
    }
  }
  return result;
}

// ---- XML (TwinCAT, PLCopen): the element tree ----

bool is_text_element(pugi::xml_node node) {
  return !node.first_child() || !node.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; });
}

std::string text_of(pugi::xml_node node) {
  std::string out;
  if (!node) return out;
  for (const pugi::xml_node c : node.children()) {
    if (c.type() == pugi::node_cdata || c.type() == pugi::node_pcdata) out += c.value();
  }
  return out;
}

bool uses_cdata(pugi::xml_node node) {
  return static_cast<bool>(node.find_child([](pugi::xml_node c) { return c.type() == pugi::node_cdata; }));
}

void set_text(pugi::xml_node node, const std::string& text, bool cdata) {
  while (node.first_child()) node.remove_child(node.first_child());
  if (text.empty()) return;
  node.append_child(cdata ? pugi::node_cdata : pugi::node_pcdata).set_value(text.c_str());
}

std::vector<pugi::xml_node> element_children(pugi::xml_node node) {
  std::vector<pugi::xml_node> out;
  if (!node) return out;
  for (const pugi::xml_node c : node.children()) {
    if (c.type() == pugi::node_element) out.push_back(c);
  }
  return out;
}

const char* name_of(pugi::xml_node n) {
  return n.attribute("Name") ? n.attribute("Name").value() : n.attribute("name").value();
}

// "tag|Name" for a named element, "tag#n" (the n-th unnamed one of its tag) otherwise.
std::vector<std::string> element_keys(const std::vector<pugi::xml_node>& nodes) {
  std::vector<std::string> keys;
  std::map<std::string, int> unnamed;
  for (const pugi::xml_node n : nodes) {
    const char* name = name_of(n);
    if (*name != '\0') {
      keys.push_back(fmt::format("{}|{}", n.name(), name));
    } else {
      keys.push_back(fmt::format("{}#{}", n.name(), unnamed[n.name()]++));
    }
  }
  return keys;
}

// Keys must be unique, or align() pairs every twin with the first one's versions and drops the
// rest. A name siblings share in any version (CODESYS writes one <data name=".../pou"> per POU
// in an <addData>) is told apart in all three by the first child element's tag and name, then
// by its place among the remaining twins.
void make_keys_unique(std::vector<pugi::xml_node>* const nodes[3], std::vector<std::string>* const keys[3]) {
  std::set<std::string> shared;
  for (int v = 0; v < 3; ++v) {
    std::map<std::string, int> count;
    for (const std::string& key : *keys[v]) {
      if (++count[key] == 2) shared.insert(key);
    }
  }
  if (shared.empty()) return;
  for (int v = 0; v < 3; ++v) {
    std::vector<std::string>& k = *keys[v];
    for (size_t i = 0; i < k.size(); ++i) {
      if (shared.count(k[i]) == 0) continue;
      const pugi::xml_node first =
          (*nodes[v])[i].find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; });
      if (first) k[i] += fmt::format(">{}|{}", first.name(), name_of(first));
    }
    std::map<std::string, int> seen;
    for (std::string& key : k) {
      const int n = seen[key]++;
      if (n > 0) key += fmt::format("#{}", n);
    }
  }
}

// An element whose child element is one of several kinds, not a list: PLCopen's holders of a
// type, a value or a body's language, TwinCAT's Implementation.
bool holds_a_choice(std::string_view tag) {
  return tag == "type" || tag == "baseType" || tag == "returnType" || tag == "initialValue" || tag == "body" ||
         tag == "Implementation";
}

// Whether two subtrees are the same (elements, attributes, text).
bool same_tree(pugi::xml_node a, pugi::xml_node b) {
  std::ostringstream sa;
  std::ostringstream sb;
  a.print(sa, "", pugi::format_raw);
  b.print(sb, "", pugi::format_raw);
  return sa.str() == sb.str();
}

class XmlMerger {
 public:
  // `attributes_are_code`: PLCopen, where names, types' parameters and initial values are
  // attributes; TwinCAT keeps its code in CDATA and its attributes are the tool's metadata.
  XmlMerger(const MergeLabels& labels, bool attributes_are_code)
      : labels_(labels), attributes_are_code_(attributes_are_code) {}

  void merge(pugi::xml_node base, pugi::xml_node ours, pugi::xml_node theirs, const std::string& path) {
    merge_attributes(base, ours, theirs, path);
    if (std::string_view(ours.name()) == "LineIds") return;  // TwinCAT recomputes them
    if (is_text_element(ours) && is_text_element(theirs) && (!base || is_text_element(base))) {
      merge_text(base, ours, theirs, path);
      return;
    }
    std::vector<pugi::xml_node> b = element_children(base);
    std::vector<pugi::xml_node> o = element_children(ours);
    std::vector<pugi::xml_node> t = element_children(theirs);
    std::vector<std::string> bk = element_keys(b);
    std::vector<std::string> ok = element_keys(o);
    std::vector<std::string> tk = element_keys(t);
    std::vector<pugi::xml_node>* const nodes[3] = {&b, &o, &t};
    std::vector<std::string>* const keys[3] = {&bk, &ok, &tk};
    make_keys_unique(nodes, keys);
    // The one child of a choice (see holds_a_choice) chosen differently on both sides, or
    // replaced on one side and changed on the other, is a conflict: ours stays; both side by
    // side would be a variable of two types, read as the first.
    if (holds_a_choice(ours.name()) && o.size() == 1 && t.size() == 1 && ok[0] != tk[0] &&
        (base ? b.size() == 1 && !same_tree(b[0], o[0]) && !same_tree(b[0], t[0]) : true)) {
      ++conflicts_;
      notes_.push_back(fmt::format("{}/{}: replaced differently on both sides: kept ours", path, ok[0]));
      return;
    }
    pugi::xml_node previous;  // the last element of the result so far, in `ours`
    for (const Slot& slot : align(bk, ok, tk)) {
      const pugi::xml_node bn = slot.base >= 0 ? b[static_cast<size_t>(slot.base)] : pugi::xml_node();
      const pugi::xml_node on = slot.ours >= 0 ? o[static_cast<size_t>(slot.ours)] : pugi::xml_node();
      const pugi::xml_node tn = slot.theirs >= 0 ? t[static_cast<size_t>(slot.theirs)] : pugi::xml_node();
      const std::string child_path = fmt::format(
          "{}/{}", path, slot.ours >= 0 ? ok[static_cast<size_t>(slot.ours)] : tk[static_cast<size_t>(slot.theirs)]);
      if (on && tn) {
        merge(bn, on, tn, child_path);
        previous = on;
      } else if (on) {
        if (bn && !same_tree(bn, on) && std::string_view(on.name()) != "LineIds") {
          ++conflicts_;
          notes_.push_back(fmt::format("{}: changed on our side, deleted on theirs: kept ours", child_path));
          previous = on;
        } else if (bn) {
          remove_with_blank(ours, on);
        } else {
          previous = on;
        }
      } else if (tn) {
        if (bn && !same_tree(bn, tn) && std::string_view(tn.name()) != "LineIds") {
          ++conflicts_;
          notes_.push_back(fmt::format("{}: deleted on our side, changed on theirs: kept theirs", child_path));
          previous = insert_copy(ours, previous, theirs, tn);
        } else if (!bn) {
          previous = insert_copy(ours, previous, theirs, tn);
        }
      }
    }
  }

  size_t conflicts() const { return conflicts_; }
  std::vector<std::string>& notes() { return notes_; }

 private:
  void merge_attributes(pugi::xml_node base, pugi::xml_node ours, pugi::xml_node theirs, const std::string& path) {
    std::vector<std::string> names;
    for (const pugi::xml_attribute a : ours.attributes()) names.emplace_back(a.name());
    for (const pugi::xml_attribute a : theirs.attributes()) {
      if (std::find(names.begin(), names.end(), a.name()) == names.end()) names.emplace_back(a.name());
    }
    for (const std::string& name : names) {
      const pugi::xml_attribute b = base.attribute(name.c_str());
      pugi::xml_attribute o = ours.attribute(name.c_str());
      const pugi::xml_attribute t = theirs.attribute(name.c_str());
      const auto value = [](pugi::xml_attribute a) { return a ? std::optional<std::string>(a.value()) : std::nullopt; };
      const std::optional<std::string> bv = value(b);
      const std::optional<std::string> ov = value(o);
      const std::optional<std::string> tv = value(t);
      // Only their change of a value we left alone applies; where both changed it, ours stays
      // (ids, product versions: metadata the vendor tool rewrites), as a conflict where the
      // value is code: their change is dropped, which must not pass silently.
      if (ov == tv || tv == bv) continue;
      if (ov != bv) {
        if (attributes_are_code_ && !is_metadata(ours, name)) {
          ++conflicts_;
          notes_.push_back(fmt::format("{}@{}: changed differently on both sides: kept ours", path, name));
        }
        continue;
      }
      if (!tv) {
        ours.remove_attribute(name.c_str());
      } else if (o) {
        o.set_value(tv->c_str());
      } else {
        ours.append_attribute(name.c_str()).set_value(tv->c_str());
      }
    }
  }

  void merge_text(pugi::xml_node base, pugi::xml_node ours, pugi::xml_node theirs, const std::string& path) {
    const std::string b = text_of(base);
    const std::string o = text_of(ours);
    const std::string t = text_of(theirs);
    if (o == t || t == b) return;
    const bool cdata = uses_cdata(ours) || uses_cdata(theirs);
    if (o == b) {
      set_text(ours, t, cdata);
      return;
    }
    MergeResult merged = merge_lines(b, o, t, labels_);
    if (merged.conflicts > 0) notes_.push_back(fmt::format("{}: conflicting changes", path));
    conflicts_ += merged.conflicts;
    set_text(ours, merged.text, cdata);
  }

  // Copies `node` of their document after `previous` in `parent` (first when null), with the
  // blank text before it on their side, so the indentation stays.
  static pugi::xml_node insert_copy(pugi::xml_node parent, pugi::xml_node previous, pugi::xml_node /*their_parent*/,
                                    pugi::xml_node node) {
    const pugi::xml_node blank = node.previous_sibling();
    const bool has_blank = blank && blank.type() == pugi::node_pcdata &&
                           std::string_view(blank.value()).find_first_not_of(" \t\r\n") == std::string_view::npos;
    pugi::xml_node inserted;
    if (previous) {
      inserted = parent.insert_copy_after(node, previous);
      if (has_blank) parent.insert_copy_before(blank, inserted);
    } else {
      const std::vector<pugi::xml_node> elements = element_children(parent);
      if (elements.empty()) {
        if (has_blank) parent.append_copy(blank);
        inserted = parent.append_copy(node);
      } else {
        inserted = parent.insert_copy_before(node, elements.front());
        if (has_blank) parent.insert_copy_before(blank, elements.front());
      }
    }
    return inserted;
  }

  static void remove_with_blank(pugi::xml_node parent, pugi::xml_node node) {
    const pugi::xml_node blank = node.previous_sibling();
    if (blank && blank.type() == pugi::node_pcdata &&
        std::string_view(blank.value()).find_first_not_of(" \t\r\n") == std::string_view::npos) {
      parent.remove_child(blank);
    }
    parent.remove_child(node);
  }

  // A PLCopen attribute the tool rewrites on every save, not code.
  static bool is_metadata(pugi::xml_node node, const std::string& name) {
    if (name == "ObjectId" || name == "creationDateTime" || name == "modificationDateTime") return true;
    for (pugi::xml_node n = node; n; n = n.parent()) {
      const std::string_view tag = n.name();
      if (tag == "fileHeader" || tag == "contentHeader") return true;
    }
    return false;
  }

  const MergeLabels& labels_;
  bool attributes_are_code_;
  size_t conflicts_ = 0;
  std::vector<std::string> notes_;
};

// A new GUID for a duplicated Id, derived from where the element is (deterministic output).
std::string derived_guid(const std::string& seed) {
  uint64_t h1 = 1469598103934665603ULL;
  uint64_t h2 = 1099511628211ULL;
  for (const char c : seed) {
    h1 = (h1 ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    h2 = (h2 ^ static_cast<unsigned char>(c)) * 14029467366897019727ULL + 1;
  }
  return fmt::format("{{{:08x}-{:04x}-4{:03x}-8{:03x}-{:012x}}}", static_cast<uint32_t>(h1 >> 32),
                     static_cast<uint32_t>((h1 >> 16) & 0xffff), static_cast<uint32_t>(h1 & 0xfff),
                     static_cast<uint32_t>(h2 >> 52), h2 & 0xffffffffffffULL);
}

void make_ids_unique(pugi::xml_node root, std::vector<std::string>& notes) {
  std::map<std::string, int> seen;
  int counter = 0;
  std::vector<pugi::xml_node> stack{root};
  while (!stack.empty()) {
    const pugi::xml_node node = stack.back();
    stack.pop_back();
    pugi::xml_attribute id = node.attribute("Id");
    // LineId elements number lines; only GUIDs ("{...}") are identities.
    if (id && id.value()[0] == '{') {
      if (++seen[keywords::upper(id.value())] > 1) {
        const std::string fresh = derived_guid(fmt::format("{}/{}/{}", node.path(), id.value(), counter++));
        notes.push_back(fmt::format("{}: duplicate Id {} replaced by {}", node.path(), id.value(), fresh));
        id.set_value(fresh.c_str());
      }
    }
    const std::vector<pugi::xml_node> children = element_children(node);
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
  }
}

// pugixml writes "<X/>" where TwinCAT writes "<X />": spelled as the input spelled it, outside
// CDATA sections and attribute values.
std::string restore_empty_element_spaces(const std::string& xml) {
  std::string out;
  out.reserve(xml.size() + xml.size() / 64);
  bool in_tag = false;
  char quote = 0;
  for (size_t i = 0; i < xml.size(); ++i) {
    const char c = xml[i];
    if (!in_tag) {
      if (xml.compare(i, 9, "<![CDATA[") == 0) {
        const size_t end = xml.find("]]>", i + 9);
        const size_t stop = end == std::string::npos ? xml.size() : end + 3;
        out.append(xml, i, stop - i);
        i = stop - 1;
        continue;
      }
      if (c == '<') in_tag = true;
      out += c;
      continue;
    }
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '/' && i + 1 < xml.size() && xml[i + 1] == '>' && !out.empty() && out.back() != ' ') {
      out += ' ';
    } else if (c == '>') {
      in_tag = false;
    }
    out += c;
  }
  return out;
}

constexpr unsigned kParseFlags = (pugi::parse_full | pugi::parse_ws_pcdata) & ~pugi::parse_eol;

MergeResult merge_xml(std::string_view base, std::string_view ours, std::string_view theirs, const MergeLabels& labels,
                      bool attributes_are_code) {
  MergeResult result;
  pugi::xml_document b;
  pugi::xml_document o;
  pugi::xml_document t;
  for (const auto& [doc, text, side] :
       {std::tuple{&b, base, "base"}, std::tuple{&o, ours, "ours"}, std::tuple{&t, theirs, "theirs"}}) {
    const pugi::xml_parse_result parsed = doc->load_buffer(text.data(), text.size(), kParseFlags);
    if (!parsed && !(text.empty() && doc == &b)) {
      result.error =
          fmt::format("malformed XML in the {} version at byte {}: {}", side, parsed.offset, parsed.description());
      result.text = std::string(ours);
      return result;
    }
  }
  const pugi::xml_node ob = o.document_element();
  const pugi::xml_node tb = t.document_element();
  if (std::string_view(ob.name()) != tb.name()) {
    result.error = fmt::format("the versions have different root elements (<{}> and <{}>)", ob.name(), tb.name());
    result.text = std::string(ours);
    return result;
  }
  XmlMerger merger(labels, attributes_are_code);
  merger.merge(b.document_element(), ob, tb, ob.name());
  result.conflicts = merger.conflicts();
  result.notes = std::move(merger.notes());
  make_ids_unique(ob, result.notes);

  const bool bom = ours.substr(0, 3) == "\xEF\xBB\xBF";
  std::ostringstream out;
  o.save(out, "", pugi::format_raw | pugi::format_no_declaration | (bom ? pugi::format_write_bom : 0u),
         pugi::encoding_utf8);
  std::string text = out.str();
  // The blank text between the declaration and the root element is not in pugixml's tree.
  const size_t declaration_end = ours.find("?>");
  const size_t root_begin = ours.find('<', declaration_end == std::string_view::npos ? 0 : declaration_end);
  if (declaration_end != std::string_view::npos && root_begin != std::string_view::npos) {
    const std::string_view blank = ours.substr(declaration_end + 2, root_begin - declaration_end - 2);
    const size_t at = text.find("?>");
    if (at != std::string::npos && blank.find_first_not_of(" \t\r\n") == std::string_view::npos) {
      text.insert(at + 2, blank);
    }
  }
  if (ours.find(" />") != std::string_view::npos) text = restore_empty_element_spaces(text);
  // Trailing blank after the root element, as ours had it.
  const size_t last = ours.find_last_of('>');
  if (last != std::string_view::npos) {
    const std::string_view tail = ours.substr(last + 1);
    if (tail.find_first_not_of(" \t\r\n") == std::string_view::npos) {
      while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
      text += tail;
    }
  }
  result.text = std::move(text);
  return result;
}

// ---- CODESYS .EXP: the exported objects ----

std::optional<std::vector<Unit>> exp_units(std::string_view path, std::string_view text) {
  const containers::ContainerDocument doc = containers::read_container(path, text);
  if (doc.kind != containers::ContainerKind::CodesysExp || doc.objects.empty()) return std::nullopt;
  std::vector<Unit> units;
  uint32_t at = 0;
  uint32_t previous = 0;  // where the previous object's header is
  std::string key = "\x01head";
  for (const containers::ContainerObject& object : doc.objects) {
    // An object starts at the "(* @NESTEDCOMMENTS" line that opens its markers, when it has
    // one: a deleted object takes its own markers along, not those of the object after it
    // (which lost them when the one before it went, and the export no longer read).
    uint32_t begin = object.file_offset;
    const size_t marker = text.rfind("(* @NESTEDCOMMENTS", object.file_offset);
    if (marker != std::string_view::npos && marker >= at && (units.empty() || marker > previous)) {
      const size_t nl = text.rfind('\n', marker);
      const size_t line = nl == std::string_view::npos ? 0 : nl + 1;
      if (text.substr(line, marker - line).find_first_not_of(" \t") == std::string_view::npos) {
        begin = static_cast<uint32_t>(line);
      }
    }
    if (begin < at) return std::nullopt;
    units.push_back({key, std::string(text.substr(at, begin - at))});
    key = fmt::format("{}:{}/{}", keywords::upper(object.kind), keywords::upper(object.path),
                      keywords::upper(object.name));
    at = begin;
    previous = object.file_offset;
  }
  units.push_back({key, std::string(text.substr(at))});
  return units;
}

}  // namespace

MergeResult merge_lines(std::string_view base, std::string_view ours, std::string_view theirs,
                        const MergeLabels& labels) {
  MergeResult result;
  if (ours == theirs || theirs == base) {
    result.text = std::string(ours);
    return result;
  }
  if (ours == base) {
    result.text = std::string(theirs);
    return result;
  }
  const Lines b = format::split_lines(base);
  const Lines o = format::split_lines(ours);
  const Lines t = format::split_lines(theirs);
  std::vector<SideChange> changes;
  for (const auto& [lines, side] : {std::pair{&o, 0}, std::pair{&t, 1}}) {
    for (const format::LineChange& c : format::diff_lines(b, *lines)) {
      SideChange s;
      s.begin = c.before_begin;
      s.end = c.before_begin + c.before_count;
      s.lines.assign(lines->begin() + static_cast<std::ptrdiff_t>(c.after_begin),
                     lines->begin() + static_cast<std::ptrdiff_t>(c.after_begin + c.after_count));
      s.side = side;
      changes.push_back(std::move(s));
    }
  }
  std::stable_sort(changes.begin(), changes.end(), [](const SideChange& x, const SideChange& y) {
    return std::tie(x.begin, x.end, x.side) < std::tie(y.begin, y.end, y.side);
  });
  size_t at = 0;
  for (size_t i = 0; i < changes.size();) {
    size_t begin = changes[i].begin;
    size_t end = changes[i].end;
    size_t j = i + 1;
    while (j < changes.size() && (changes[j].begin < end ||
                                  (changes[j].begin == end && (changes[j].begin == changes[j].end || begin == end)))) {
      end = std::max(end, changes[j].end);
      ++j;
    }
    append_lines(result.text, b, at, begin);
    bool ours_changed = false;
    bool theirs_changed = false;
    for (size_t k = i; k < j; ++k) (changes[k].side == 0 ? ours_changed : theirs_changed) = true;
    const std::string mine = apply_side(b, changes, i, j, 0, begin, end);
    const std::string other = apply_side(b, changes, i, j, 1, begin, end);
    if (!theirs_changed || mine == other) {
      result.text += mine;
    } else if (!ours_changed) {
      result.text += other;
    } else {
      append_conflict(result.text, mine, other, labels, line_end_of(ours));
      ++result.conflicts;
    }
    at = end;
    i = j;
  }
  append_lines(result.text, b, at, b.size());
  return result;
}

MergeResult merge_file(std::string_view path, std::string_view base, std::string_view ours, std::string_view theirs,
                       const MergeLabels& labels) {
  const containers::ContainerKind kind = containers::detect_container(path, ours);
  if (kind == containers::ContainerKind::TwinCat || kind == containers::ContainerKind::PlcOpen) {
    return merge_xml(base, ours, theirs, labels, kind == containers::ContainerKind::PlcOpen);
  }
  // Text: decoded to UTF-8 for the parser, written back in our side's encoding.
  const source::DecodedText b = source::decode(base);
  const source::DecodedText o = source::decode(ours);
  const source::DecodedText t = source::decode(theirs);
  if (o.is_binary || t.is_binary || (b.is_binary && !base.empty())) {
    MergeResult result;
    result.text = std::string(ours);
    result.error = "binary content: not merged";
    return result;
  }
  std::optional<std::vector<Unit>> bu;
  std::optional<std::vector<Unit>> ou;
  std::optional<std::vector<Unit>> tu;
  if (kind == containers::ContainerKind::CodesysExp) {
    bu = exp_units(path, b.utf8);
    ou = exp_units(path, o.utf8);
    tu = exp_units(path, t.utf8);
  } else {
    bu = st_units(b.utf8);
    ou = st_units(o.utf8);
    tu = st_units(t.utf8);
  }
  MergeResult result;
  if (bu && ou && tu && !has_duplicates(unit_keys(*bu)) && !has_duplicates(unit_keys(*ou)) &&
      !has_duplicates(unit_keys(*tu))) {
    result = merge_units(*bu, *ou, *tu, labels);
  } else {
    result = merge_lines(b.utf8, o.utf8, t.utf8, labels);
    result.notes.emplace_back("merged line by line (a version does not parse into named objects)");
  }
  std::optional<std::string> encoded = source::encode(result.text, o.encoding, o.had_bom);
  if (!encoded) {
    encoded = source::encode(result.text, source::Encoding::Utf8, o.had_bom);
    result.notes.emplace_back("written as UTF-8: their text has characters our encoding cannot hold");
  }
  result.text = std::move(*encoded);
  return result;
}

}  // namespace rung::vcs
