#include "parser/containers/twincat_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <pugixml.hpp>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "parser/containers/xml_text.hpp"
#include "parser/source/line_index.hpp"

namespace rung::containers {
namespace {

// No end-of-line normalisation and no entity expansion: node values stay
// byte-identical to the file, so offset_debug() + value length is exactly the
// node's extent and positions can be mapped 1:1. Entities are expanded by
// append_escaped_text, which keeps the mapping.

bool is_text_language(std::string_view name) {
  return name == "ST" || name == "IL";
}

std::string kind_of(std::string_view element) {
  if (element == "Itf") return "ITF";
  return std::string(element);  // POU, DUT, GVL
}

class TwinCatReader {
 public:
  explicit TwinCatReader(std::string_view text) : text_(text) {}

  ContainerDocument read() {
    pugi::xml_document xml;
    if (auto problem = load_container_xml(xml, text_)) issues_.push_back(std::move(*problem));

    const pugi::xml_node root = xml.document_element();
    if (root && std::string_view(root.name()) != "TcPlcObject") {
      issue(offset_of(root),
            fmt::format("not a TwinCAT PLC object: the root element is <{}>, not <TcPlcObject>", root.name()));
    } else if (root) {
      read_objects(root);
    }
    ContainerDocument doc = builder_.finish(ContainerKind::TwinCat);
    doc.issues = std::move(issues_);
    doc.objects = std::move(objects_);
    return doc;
  }

 private:
  void read_objects(pugi::xml_node root) {
    for (const pugi::xml_node element : root.children()) {
      if (element.type() != pugi::node_element) continue;
      const std::string_view tag = element.name();
      if (tag == "POU" || tag == "DUT" || tag == "GVL" || tag == "Itf") {
        read_object(element, kind_of(tag));
      } else {
        ContainerObject other;
        other.name = attribute(element, "Name");
        other.kind = std::string(tag);
        other.file_offset = offset_of(element);
        other.note = fmt::format("TwinCAT <{}> object holds no PLC source; skipped", tag);
        objects_.push_back(std::move(other));
      }
    }
  }

  void read_object(pugi::xml_node element, std::string kind) {
    owner_ = attribute(element, "Name");
    ContainerObject main;
    main.name = owner_;
    main.kind = std::move(kind);
    main.file_offset = offset_of(element);

    add_text(element.child("Declaration"), "declaration");
    add_implementation(element, "implementation", main);
    objects_.push_back(std::move(main));

    for (const pugi::xml_node method : element.children("Method")) {
      ContainerObject object = member(method, "METHOD");
      const std::string prefix = "method " + attribute(method, "Name");
      add_text(method.child("Declaration"), prefix + "/declaration");
      add_implementation(method, prefix + "/implementation", object);
      objects_.push_back(std::move(object));
    }
    for (const pugi::xml_node property : element.children("Property")) {
      objects_.push_back(member(property, "PROPERTY"));
      const std::string prefix = "property " + attribute(property, "Name");
      add_text(property.child("Declaration"), prefix + "/declaration");
      for (const auto& [tag, keyword] : {std::pair{"Get", "GET\n"}, std::pair{"Set", "SET\n"}}) {
        const pugi::xml_node accessor = property.child(tag);
        if (!accessor) continue;
        const std::string accessor_role = prefix + (tag == std::string_view("Get") ? "/get" : "/set");
        add_header(keyword, accessor_role);
        add_text(accessor.child("Declaration"), accessor_role + "/declaration");
        ContainerObject& owner = objects_.back();
        add_implementation(accessor, accessor_role + "/implementation", owner);
      }
    }
    for (const auto& [tag, kind, role] :
         {std::tuple{"Action", "ACTION", "action "}, std::tuple{"Transition", "TRANSITION", "transition "}}) {
      for (const pugi::xml_node sub : element.children(tag)) {
        ContainerObject object = member(sub, kind);
        const std::string name = attribute(sub, "Name");
        // `ACTION name:` / `TRANSITION name:` headers: the grammar's object forms; a
        // transition body is usually one boolean expression. An action or transition
        // without text to read (graphical, or empty as SFC step actions often are) gets
        // no header: an empty `ACTION name:` directly before a `TRANSITION` header does
        // not parse, and there is nothing in it for the grammar anyway.
        if (has_code(text_body(sub))) {
          add_header(fmt::format("{} {}:\n", kind, name), role + name);
          add_implementation(sub, role + name, object);
        } else if (const pugi::xml_node body = body_of(sub); body && !is_text_language(body.name())) {
          object.language = body.name();
          object.note = fmt::format("{} implementation is graphical; not read as text", body.name());
        } else {
          if (body) object.language = body.name();
          object.note = "empty; not in the virtual text";
        }
        objects_.push_back(std::move(object));
      }
    }
  }

  ContainerObject member(pugi::xml_node element, std::string kind) const {
    ContainerObject object;
    object.name = owner_ + "." + attribute(element, "Name");
    object.kind = std::move(kind);
    object.file_offset = offset_of(element);
    return object;
  }

  // The body element of `owner`'s implementation (<ST>, <IL>, <SFC>, <NWL>...), or null.
  static pugi::xml_node body_of(pugi::xml_node owner) {
    for (const pugi::xml_node body : owner.child("Implementation").children()) {
      if (body.type() == pugi::node_element) return body;
    }
    return {};
  }

  // The textual body of `owner` (<ST> or <IL>), or null when it has none or a graphical one.
  static pugi::xml_node text_body(pugi::xml_node owner) {
    const pugi::xml_node body = body_of(owner);
    return body && is_text_language(body.name()) ? body : pugi::xml_node();
  }

  // Whether `element` holds character data other than blanks (escaped or CDATA).
  static bool has_code(pugi::xml_node element) {
    for (const pugi::xml_node node : element.children()) {
      if (node.type() != pugi::node_cdata && node.type() != pugi::node_pcdata) continue;
      const std::string_view value = node.value();
      if (value.find_first_not_of(" \t\r\n") != std::string_view::npos) return true;
    }
    return false;
  }

  // The implementation of `owner`: its <ST> (or textual <IL>) becomes virtual
  // text; a graphical body (LD/FBD as <NWL>, <SFC>, <CFC>...) is recorded on the object.
  void add_implementation(pugi::xml_node owner, const std::string& role, ContainerObject& object) {
    const pugi::xml_node body = body_of(owner);
    if (!body) return;
    const std::string_view language = body.name();
    if (object.language.empty()) object.language = std::string(language);
    if (is_text_language(language)) {
      add_text(body, role);
    } else if (object.note.empty()) {
      object.note = fmt::format("{} implementation is graphical; not read as text", language);
    }
  }

  // The character data of `element` (CDATA sections and escaped text) as one part.
  void add_text(pugi::xml_node element, const std::string& role) {
    if (!element) return;
    struct Piece {
      uint32_t offset;
      std::string_view raw;
      bool escaped;
    };
    std::vector<Piece> pieces;
    for (const pugi::xml_node node : element.children()) {
      const bool cdata = node.type() == pugi::node_cdata;
      if (!cdata && node.type() != pugi::node_pcdata) continue;
      const std::string_view value = node.value();
      const ptrdiff_t at = node.offset_debug();
      const bool located = at >= 0 && static_cast<size_t>(at) + value.size() <= text_.size() &&
                           text_.substr(static_cast<size_t>(at), value.size()) == value;
      if (!located) {
        // Cannot happen with the parse flags above; kept so a surprise in
        // pugixml degrades positions instead of dropping code.
        issue(0, fmt::format("could not locate the text of <{}> in the file; positions in it are approximate",
                             element.name()));
        builder_.append_synthetic(value, role, owner_);
        continue;
      }
      if (!value.empty()) pieces.push_back({static_cast<uint32_t>(at), value, !cdata});
    }
    if (pieces.empty()) return;
    separate();
    for (const Piece& piece : pieces) {
      if (piece.escaped) {
        append_escaped_text(builder_, piece.raw, piece.offset, role, owner_);
      } else {
        builder_.append_real(piece.raw, piece.offset, role, owner_);
      }
    }
    need_separator_ = true;
  }

  void add_header(std::string_view line, const std::string& role) {
    separate();
    builder_.append_synthetic(line, role, owner_);
    need_separator_ = false;
  }

  void separate() {
    if (need_separator_) builder_.append_synthetic("\n", "separator", owner_);
    need_separator_ = false;
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
  VirtualTextBuilder builder_;
  std::string owner_;
  bool need_separator_ = false;
  std::vector<ContainerIssue> issues_;
  std::vector<ContainerObject> objects_;
};

}  // namespace

ContainerDocument read_twincat(std::string_view text) {
  return TwinCatReader(text).read();
}

}  // namespace rung::containers
