#include "tests/vcs/merge_properties.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "parser/containers/read_container.hpp"
#include "parser/diagnostic.hpp"
#include "parser/document.hpp"
#include "parser/keywords.hpp"
#include "parser/source/decode.hpp"
#include "vcs/object_model.hpp"

namespace rung::test {
namespace {

using containers::ContainerKind;

// As merge_file reads XML: every node, blank text kept, line ends as written.
constexpr unsigned kXmlFlags = (pugi::parse_full | pugi::parse_ws_pcdata) & ~pugi::parse_eol;

bool is_xml(ContainerKind kind) {
  return kind == ContainerKind::TwinCat || kind == ContainerKind::PlcOpen;
}

// Shortened for messages: a whole file in every violation would bury the point.
std::string shown(std::string_view text) {
  constexpr size_t kMax = 240;
  std::string out(text.substr(0, kMax));
  if (text.size() > kMax) out += "...";
  std::replace(out.begin(), out.end(), '\x02', '|');
  return out;
}

// Visits every text node (plain and CDATA) under `node` in document order.
void for_each_text(pugi::xml_node node, const std::function<void(pugi::xml_node)>& visit) {
  for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) visit(child);
    for_each_text(child, visit);
  }
}

// The text a person would see conflict markers in: the file's decoded text, and for XML the
// text nodes' values (markers in plain XML text are written escaped).
std::string visible_text(ContainerKind kind, std::string_view bytes) {
  const source::DecodedText decoded = source::decode(bytes);
  std::string out = decoded.utf8;
  if (is_xml(kind)) {
    pugi::xml_document doc;
    if (doc.load_buffer(bytes.data(), bytes.size(), kXmlFlags)) {
      for_each_text(doc, [&](pugi::xml_node n) { out += n.value(); });
    }
  }
  return out;
}

bool has_marker_text(ContainerKind kind, std::string_view bytes) {
  const std::string text = visible_text(kind, bytes);
  return text.find("<<<<<<<") != std::string::npos || text.find("=======") != std::string::npos ||
         text.find(">>>>>>>") != std::string::npos;
}

// A text with each conflict region (as merge_lines writes them) resolved to one side.
struct Resolved {
  std::string ours;
  std::string theirs;
  size_t regions = 0;
  std::string error;
};

Resolved resolve_markers(std::string_view text, const vcs::MergeLabels& labels) {
  enum class In { Both, Ours, Theirs };
  const std::string start = "<<<<<<< " + labels.ours;
  const std::string end = ">>>>>>> " + labels.theirs;
  Resolved r;
  In in = In::Both;
  size_t at = 0;
  while (at < text.size() && r.error.empty()) {
    const size_t nl = text.find('\n', at);
    const size_t next = nl == std::string_view::npos ? text.size() : nl + 1;
    const std::string_view line = text.substr(at, next - at);
    std::string_view bare = line;
    if (!bare.empty() && bare.back() == '\n') bare.remove_suffix(1);
    if (!bare.empty() && bare.back() == '\r') bare.remove_suffix(1);
    if (bare == start) {
      if (in != In::Both) r.error = "a conflict region opens inside another";
      in = In::Ours;
    } else if (bare == "=======") {
      if (in != In::Ours) r.error = "a \"=======\" line outside a conflict region";
      in = In::Theirs;
    } else if (bare == end) {
      if (in != In::Theirs) r.error = "a \">>>>>>>\" line without its \"=======\"";
      in = In::Both;
      ++r.regions;
    } else {
      if (in != In::Theirs) r.ours += line;
      if (in != In::Ours) r.theirs += line;
    }
    at = next;
  }
  if (r.error.empty() && in != In::Both) r.error = "a conflict region is not closed";
  return r;
}

// The merged file with its conflict regions resolved to each side, as bytes rung reads.
Resolved resolve_file(ContainerKind kind, std::string_view merged, const vcs::MergeLabels& labels) {
  Resolved out;
  if (!is_xml(kind)) {
    const source::DecodedText decoded = source::decode(merged);
    if (decoded.is_binary) {
      out.error = "the merged file reads as binary";
      return out;
    }
    return resolve_markers(decoded.utf8, labels);
  }
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(merged.data(), merged.size(), kXmlFlags);
  if (!parsed) {
    out.error =
        fmt::format("the merged file is not well-formed XML (byte {}: {})", parsed.offset, parsed.description());
    return out;
  }
  // Each text node resolved on its own: merge_xml writes regions only inside one text.
  std::vector<pugi::xml_node> nodes;
  std::vector<Resolved> texts;
  for_each_text(doc, [&](pugi::xml_node n) {
    nodes.push_back(n);
    texts.push_back(resolve_markers(n.value(), labels));
  });
  for (size_t i = 0; i < texts.size(); ++i) {
    out.regions += texts[i].regions;
    if (out.error.empty() && !texts[i].error.empty()) {
      out.error = fmt::format("{} in the text of <{}>", texts[i].error, nodes[i].parent().name());
    }
  }
  const auto save = [&](std::string Resolved::*side) {
    for (size_t i = 0; i < nodes.size(); ++i) nodes[i].set_value((texts[i].*side).c_str());
    std::ostringstream s;
    doc.save(s, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
    return s.str();
  };
  out.ours = save(&Resolved::ours);
  out.theirs = save(&Resolved::theirs);
  return out;
}

// ---- comparing versions through the object model ----

constexpr std::string_view kAbsent = "\x04(absent)";

// A value in five versions: base, ours, theirs, and the merged file resolved to ours and to
// theirs (for a clean merge the last two are the merged file).
struct Five {
  std::string base, ours, theirs, merged_ours, merged_theirs;
};

// Whether a side removed a thing the other side changed, among the things of one level (the
// objects of the file, the members of an object, the declarations of a member). What that side
// added may then be the thing renamed, and a merge that follows the rename (line by line, or by
// an XML Name the rename left alone) rightly carries the other side's change into it.
struct Renames {
  bool ours = false;
  bool theirs = false;

  void see(const Five& v) {
    if (v.base == kAbsent) return;
    ours = ours || (v.ours == kAbsent && v.theirs != v.base);
    theirs = theirs || (v.theirs == kAbsent && v.ours != v.base);
  }
};

// What the merge must have done with one thing (object, member, declaration field) whose
// versions are `v`: the change only one side made is in that side's resolution; a thing
// neither side changed, or both changed alike, is unchanged in both. Returns "" when it holds.
std::string one_sided_rule(const Five& v, const Renames& renames, bool conflicted, bool moved_ours, bool moved_theirs) {
  const bool ours_changed = v.ours != v.base || moved_ours;
  const bool theirs_changed = v.theirs != v.base || moved_theirs;
  const auto describe = [](std::string_view what, std::string_view expected, std::string_view got) {
    return fmt::format("{}: expected {}, got {}", what, shown(expected), shown(got));
  };
  // Perhaps a rename (see Renames): only its presence is certain.
  if (v.base == kAbsent && v.theirs == kAbsent && v.ours != kAbsent && renames.ours) {
    return v.merged_ours == kAbsent ? describe("our addition is lost", v.ours, v.merged_ours) : std::string();
  }
  if (v.base == kAbsent && v.ours == kAbsent && v.theirs != kAbsent && renames.theirs) {
    return v.merged_theirs == kAbsent ? describe("their addition is lost", v.theirs, v.merged_theirs) : std::string();
  }
  // Both: the caller looks closer. A thing one side moved and the other changed is both: to
  // diff3 the move is a deletion and an insertion, and either may undo the other's change.
  if (ours_changed && theirs_changed && (v.ours != v.theirs || moved_ours || moved_theirs)) return {};
  // With conflicts, a thing neither side changed (or both alike) may sit in one side's half of
  // a region only: one side moved it (diff3 sees a deletion and an insertion) and the insertion
  // conflicts. Then one resolution has it, and the other has it in the region it conflicts in.
  if ((!ours_changed && !theirs_changed) || (ours_changed && theirs_changed)) {
    if (conflicted && (v.merged_ours == v.ours || v.merged_theirs == v.ours)) return {};
  }
  if (!ours_changed && !theirs_changed) {
    if (v.merged_ours != v.base)
      return describe("changed by neither side but changed by the merge", v.base, v.merged_ours);
    if (v.merged_theirs != v.base) {
      return describe("changed by neither side but changed by the merge (their resolution)", v.base, v.merged_theirs);
    }
    return {};
  }
  if (ours_changed && theirs_changed) {  // the same change on both sides
    if (v.merged_ours != v.ours)
      return describe("changed alike on both sides, the merge lost it", v.ours, v.merged_ours);
    if (v.merged_theirs != v.ours) {
      return describe("changed alike on both sides, the merge lost it (their resolution)", v.ours, v.merged_theirs);
    }
    return {};
  }
  if (ours_changed && v.merged_ours != v.ours) return describe("our change is lost", v.ours, v.merged_ours);
  if (theirs_changed && v.merged_theirs != v.theirs) return describe("their change is lost", v.theirs, v.merged_theirs);
  return {};
}

bool changed_on_both_sides_differently(const Five& v) {
  return v.ours != v.base && v.theirs != v.base && v.ours != v.theirs;
}

// Things of one version by an upper-case key; a key used twice is ambiguous (null).
template <typename T>
struct Index {
  std::map<std::string, const T*> items;
  std::set<std::string> ambiguous;
  std::vector<std::string> order;  // the keys in file order

  void add(const std::string& key, const T* item) {
    if (!items.emplace(key, item).second) ambiguous.insert(key);
    order.push_back(key);
  }
  const T* find(const std::string& key) const {
    const auto it = items.find(key);
    return it == items.end() ? nullptr : it->second;
  }
};

// The things each side moved: those whose neighbours among the things both base and that
// side hold differ (over-approximated: a neighbour of a moved thing counts as moved too).
struct Moves {
  std::set<std::string> ours;
  std::set<std::string> theirs;
};

std::set<std::string> moved(const std::vector<std::string>& base, const std::vector<std::string>& side) {
  const std::set<std::string> in_base(base.begin(), base.end());
  const std::set<std::string> in_side(side.begin(), side.end());
  const auto common = [](const std::vector<std::string>& order, const std::set<std::string>& other) {
    std::vector<std::string> out;
    for (const std::string& key : order) {
      if (other.count(key) > 0) out.push_back(key);
    }
    return out;
  };
  const auto neighbours = [](const std::vector<std::string>& order) {
    std::map<std::string, std::pair<std::string, std::string>> out;
    for (size_t i = 0; i < order.size(); ++i) {
      out[order[i]] = {i > 0 ? order[i - 1] : std::string(), i + 1 < order.size() ? order[i + 1] : std::string()};
    }
    return out;
  };
  const auto before = neighbours(common(base, in_side));
  const auto after = neighbours(common(side, in_base));
  std::set<std::string> out;
  for (const auto& [key, around] : after) {
    const auto it = before.find(key);
    if (it == before.end() || it->second != around) out.insert(key);
  }
  return out;
}

std::string object_key(const vcs::Object& o) {
  return fmt::format("{}:{}", o.name_space(), keywords::upper(o.name));
}

std::string object_value(const vcs::Object* o) {
  return o == nullptr ? std::string(kAbsent) : o->name + '\x02' + o->content_key();
}

std::string part_value(const vcs::Part* p) {
  if (p == nullptr) return std::string(kAbsent);
  return fmt::format("{}\x02{}\x02{}\x02{}", p->kind, p->declaration_key, p->has_body ? "body" : "no body",
                     p->body_key);
}

// By name only: the block is a field, so that a block's new kind (VAR to VAR_INPUT) is a change
// of its declarations, not their deletion and the addition of others.
std::string declaration_key(const vcs::Declaration& d) {
  return keywords::upper(d.name);
}

// The five versions of the file, read through the object model.
struct Versions {
  vcs::FileObjects base, ours, theirs, merged_ours, merged_theirs;
};

// One level of things in the five versions (the objects of the file, the members of an object,
// the declarations of a member), by key, with what holds for the level as a whole.
template <typename T>
class Level {
 public:
  // `items[i]` is the list of things of version i (null: the version lacks their owner);
  // `value` gives the Five's value of one (null: absent).
  template <typename Key, typename Value>
  Level(const std::array<const std::vector<T>*, 5>& items, Key key, Value value) : indexes_(5) {
    std::set<std::string> keys;
    for (size_t i = 0; i < 5; ++i) {
      if (items[i] == nullptr) continue;
      for (const T& item : *items[i]) {
        indexes_[i].add(key(item), &item);
        keys.insert(key(item));
      }
    }
    for (const std::string& k : keys) {
      if (ambiguous(k)) continue;
      const Five v = five([&](size_t i) { return value(find(i, k)); });
      renames_.see(v);
      values_.emplace(k, v);
    }
    moves_ = Moves{moved(indexes_[0].order, indexes_[1].order), moved(indexes_[0].order, indexes_[2].order)};
  }

  // The values of the keys no version uses twice.
  const std::map<std::string, Five>& values() const { return values_; }
  const T* find(size_t version, const std::string& key) const { return indexes_[version].find(key); }
  bool ambiguous(const std::string& key) const {
    return std::any_of(indexes_.begin(), indexes_.end(), [&](const auto& i) { return i.ambiguous.count(key) > 0; });
  }
  bool any_ambiguous() const {
    return std::any_of(indexes_.begin(), indexes_.end(), [](const auto& i) { return !i.ambiguous.empty(); });
  }
  std::string rule(const std::string& key, const Five& v, bool conflicted) const {
    return one_sided_rule(v, renames_, conflicted, moves_.ours.count(key) > 0, moves_.theirs.count(key) > 0);
  }

  template <typename F>
  static Five five(F&& value) {
    return Five{value(0), value(1), value(2), value(3), value(4)};
  }

 private:
  std::vector<Index<T>> indexes_;
  std::map<std::string, Five> values_;
  Renames renames_;
  Moves moves_;
};

class ObjectChecker {
 public:
  ObjectChecker(const Versions& versions, bool conflicted, const std::set<std::string>& exempt,
                std::vector<std::string>& violations)
      : objects_(std::array<const std::vector<vcs::Object>*, 5>{&versions.base.objects, &versions.ours.objects,
                                                                &versions.theirs.objects, &versions.merged_ours.objects,
                                                                &versions.merged_theirs.objects},
                 object_key, object_value),
        conflicted_(conflicted),
        exempt_(exempt),
        violations_(violations) {}

  // Keys of the objects changed on both sides differently (after check()).
  const std::vector<std::string>& both_changed() const { return both_changed_; }
  bool any_ambiguous() const { return objects_.any_ambiguous(); }

  void check() {
    for (const auto& [key, v] : objects_.values()) {
      if (changed_on_both_sides_differently(v)) both_changed_.push_back(key);
      if (is_exempt(key.substr(key.find(':') + 1))) continue;
      const std::string broken = objects_.rule(key, v, conflicted_);
      if (!broken.empty()) violations_.push_back(fmt::format("object {}: {}", key, broken));
      std::array<const std::vector<vcs::Part>*, 5> parts{};
      for (size_t i = 0; i < 5; ++i) {
        const vcs::Object* o = objects_.find(i, key);
        parts[i] = o == nullptr ? nullptr : &o->parts;
      }
      if (changed_on_both_sides_differently(v) && parts[1] != nullptr && parts[2] != nullptr) check_parts(key, parts);
    }
  }

 private:
  bool is_exempt(const std::string& upper_name) const { return exempt_.count(upper_name) > 0; }

  // The members of an object both sides changed: the same rule member by member.
  void check_parts(const std::string& object, const std::array<const std::vector<vcs::Part>*, 5>& items) {
    const Level<vcs::Part> parts(
        items, [](const vcs::Part& p) { return keywords::upper(p.name); }, part_value);
    for (const auto& [key, v] : parts.values()) {
      const size_t dot = key.rfind('.');
      if (!key.empty() && is_exempt(key.substr(dot == std::string::npos ? 0 : dot + 1))) continue;
      const std::string where = key.empty() ? object : fmt::format("{}.{}", object, key);
      const std::string broken = parts.rule(key, v, conflicted_);
      if (!broken.empty()) violations_.push_back(fmt::format("member {}: {}", where, broken));
      std::array<const std::vector<vcs::Declaration>*, 5> declarations{};
      for (size_t i = 0; i < 5; ++i) {
        const vcs::Part* p = parts.find(i, key);
        declarations[i] = p == nullptr ? nullptr : &p->declarations;
      }
      if (changed_on_both_sides_differently(v) && declarations[1] != nullptr && declarations[2] != nullptr) {
        check_declarations(where, declarations);
      }
    }
  }

  // The declarations of a member both sides changed: each field on its own, so that one
  // side's new type and the other's new initial value of one variable must both arrive.
  void check_declarations(const std::string& member, const std::array<const std::vector<vcs::Declaration>*, 5>& items) {
    const Level<vcs::Declaration> declarations(items, declaration_key, [](const vcs::Declaration* d) {
      return d == nullptr ? std::string(kAbsent)
                          : fmt::format("{}\x02{}\x02{}\x02{}\x02{}", d->block, d->type_key, d->value_key, d->other_key,
                                        d->attributes);
    });
    using Field = std::string vcs::Declaration::*;
    const std::pair<const char*, Field> fields[] = {{"block", &vcs::Declaration::block},
                                                    {"type", &vcs::Declaration::type_key},
                                                    {"initial value", &vcs::Declaration::value_key},
                                                    {"AT/arguments", &vcs::Declaration::other_key},
                                                    {"attributes", &vcs::Declaration::attributes}};
    for (const auto& entry : declarations.values()) {
      const std::string& key = entry.first;
      if (is_exempt(key)) continue;
      for (const std::pair<const char*, Field>& field : fields) {
        const Five v = Level<vcs::Declaration>::five([&](size_t i) {
          const vcs::Declaration* d = declarations.find(i, key);
          return d == nullptr ? std::string(kAbsent) : d->*field.second;
        });
        const std::string broken = declarations.rule(key, v, conflicted_);
        if (!broken.empty()) {
          violations_.push_back(fmt::format("{} of {} in {}: {}", field.first, key, member, broken));
        }
      }
    }
  }

  const Level<vcs::Object> objects_;
  bool conflicted_;  // the merge reported conflicts: the two resolutions may differ
  const std::set<std::string>& exempt_;
  std::vector<std::string>& violations_;
  std::vector<std::string> both_changed_;
};

// The names in the paths of XML element conflicts the merge resolved to one side ("POU|FB_A/
// Method|M_B: deleted on our side, changed on theirs: kept theirs"): reported conflicts without
// markers, so the dropped side's change is expected to be missing there.
std::set<std::string> kept_names(const std::vector<std::string>& notes, size_t& kept) {
  std::set<std::string> names;
  for (const std::string& note : notes) {
    if (note.find(": kept ") == std::string::npos) continue;
    ++kept;
    const std::string path = note.substr(0, note.find(": "));
    size_t at = 0;
    while ((at = path.find('|', at)) != std::string::npos) {
      const size_t end = path.find('/', at);
      names.insert(keywords::upper(path.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1)));
      at = end == std::string::npos ? path.size() : end;
    }
  }
  return names;
}

void check_unique_ids(std::string_view merged, std::vector<std::string>& violations) {
  pugi::xml_document doc;
  if (!doc.load_buffer(merged.data(), merged.size(), kXmlFlags)) return;  // reported elsewhere
  std::set<std::string> seen;
  for (const pugi::xpath_node n : doc.select_nodes("//*[starts-with(@Id, '{')]")) {
    const std::string id = keywords::upper(n.node().attribute("Id").value());
    if (!seen.insert(id).second) violations.push_back(fmt::format("the GUID Id {} is used twice", id));
  }
}

}  // namespace

bool parses_cleanly(std::string_view path, std::string_view bytes) {
  // The diagnostics `rung parse` prints: syntax errors beyond the tree's ERROR nodes (a stray
  // END_IF), container and encoding errors.
  const Document doc = Document::from_bytes(std::string(path), bytes);
  return std::none_of(doc.diagnostics().begin(), doc.diagnostics().end(),
                      [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

MergeCheck check_merge(std::string_view path, std::string_view base, std::string_view ours, std::string_view theirs) {
  MergeCheck check;
  check.merge = vcs::merge_file(path, base, ours, theirs);
  // git may run the driver again on the same versions (rerere, a retried rebase).
  const vcs::MergeResult again = vcs::merge_file(path, base, ours, theirs);
  if (again.text != check.merge.text || again.conflicts != check.merge.conflicts) {
    check.violation = "merging the same versions twice gives different results\n";
  }
  check.violation += merge_violations(path, base, ours, theirs, check.merge, &check.objects_compared);
  return check;
}

std::string merge_violations(std::string_view path, std::string_view base, std::string_view ours,
                             std::string_view theirs, const vcs::MergeResult& merge, bool* objects_compared) {
  const vcs::MergeLabels labels;
  std::vector<std::string> violations;
  const auto done = [&]() {
    std::string out;
    for (const std::string& v : violations) out += v + "\n";
    return out;
  };
  if (!merge.error.empty()) {
    if (merge.text != ours) {
      violations.push_back(fmt::format("the merge failed ({}) but did not keep ours", merge.error));
    }
    return done();
  }

  const ContainerKind kind = containers::detect_container(path, ours);
  if (is_xml(kind)) {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(merge.text.data(), merge.text.size(), kXmlFlags);
    if (!parsed) {
      violations.push_back(
          fmt::format("the merged file is not well-formed XML (byte {}: {})", parsed.offset, parsed.description()));
      return done();
    }
    check_unique_ids(merge.text, violations);
  }
  for (const std::string_view version : {base, ours, theirs}) {
    if (has_marker_text(kind, version)) return done();
  }

  // Every conflict is visible: a marked region, or a note that names the side kept.
  const Resolved resolved = resolve_file(kind, merge.text, labels);
  if (!resolved.error.empty()) {
    violations.push_back(fmt::format("conflict markers: {}", resolved.error));
    return done();
  }
  size_t kept = 0;
  const std::set<std::string> exempt = kept_names(merge.notes, kept);
  if (resolved.regions + kept != merge.conflicts) {
    violations.push_back(
        fmt::format("{} conflicts reported, but the file holds {} marked regions and {} kept-side notes",
                    merge.conflicts, resolved.regions, kept));
  }

  // Plain text versions are read decoded, as the resolved texts are.
  const auto text_of = [&](std::string_view bytes) {
    return is_xml(kind) ? std::string(bytes) : source::decode(bytes).utf8;
  };
  Versions versions;
  versions.base = vcs::read_objects(path, text_of(base));
  versions.ours = vcs::read_objects(path, text_of(ours));
  versions.theirs = vcs::read_objects(path, text_of(theirs));
  versions.merged_ours = vcs::read_objects(path, resolved.ours);
  // A clean merge resolves to itself both ways: read once.
  versions.merged_theirs =
      resolved.theirs == resolved.ours ? versions.merged_ours : vcs::read_objects(path, resolved.theirs);

  if (versions.base.errors.empty() && versions.ours.errors.empty() && versions.theirs.errors.empty()) {
    for (const auto& [side, file] :
         {std::pair{"", &versions.merged_ours}, std::pair{" (theirs)", &versions.merged_theirs}}) {
      if (!file->errors.empty()) {
        violations.push_back(fmt::format("the merged file{} does not read back: {}", side, file->errors.front()));
      }
    }
  }

  // The object model of code with syntax errors depends on error recovery, which is not
  // local: one broken line can change how its neighbours read. Objects are compared only when
  // the versions and the resolved merge parse. A line merge can make code that does not parse
  // of two edits of one object (as any textual merge can) or, with conflicts, of changes the
  // model does not see (a moved END_VAR); a clean merge that does not parse although no object
  // changed on both sides is a violation of its own, below.
  // Merged line by line as a whole (a version without named objects), the file is one unit
  // both sides changed, and its objects, if any, are not what the merge went by: a line that
  // declares a variable in one version can be read otherwise in another.
  const bool whole_file_by_lines = std::any_of(merge.notes.begin(), merge.notes.end(), [](const std::string& note) {
    return note.find("merged line by line") != std::string::npos;
  });
  const bool versions_parse = parses_cleanly(path, base) && parses_cleanly(path, ours) && parses_cleanly(path, theirs);
  if (!versions_parse || whole_file_by_lines) return done();
  std::vector<std::string> object_violations;
  ObjectChecker objects(versions, merge.conflicts > 0, exempt, object_violations);
  objects.check();
  const bool merged_parses = parses_cleanly(path, resolved.ours) &&
                             (resolved.theirs == resolved.ours || parses_cleanly(path, resolved.theirs));
  if (merged_parses) {
    if (objects_compared != nullptr) *objects_compared = true;
    violations.insert(violations.end(), object_violations.begin(), object_violations.end());
  } else if (merge.conflicts == 0 && objects.both_changed().empty() && !objects.any_ambiguous()) {
    violations.emplace_back("the versions parse, no object changed on both sides, but the clean merge does not parse");
    violations.insert(violations.end(), object_violations.begin(), object_violations.end());
  }
  return done();
}

}  // namespace rung::test
