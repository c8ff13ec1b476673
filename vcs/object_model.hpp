// What a PLC source file declares, by meaning: the objects (POUs, types, global variable lists,
// configurations) with their members, declarations and bodies, each in a normal form that does
// not see whitespace, layout, keyword case, TwinCAT LineIds and GUIDs, or XML element order.
// `rung diff` compares two versions of a file through this model; `rung textconv` prints the
// text it is read from.
//
// Keys ("..._key") are the tokens of a piece of code joined by single spaces: keywords as the
// grammar names them (upper case), identifiers and strings as written, other literals upper
// case, pragmas with their blanks collapsed; comments only when ReadOptions::comments is set.
// Texts ("..._text") are the same code laid out by `rung fmt` (or as written when it does not
// format), for people.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rung::vcs {

// One declared name: a variable of a VAR block, a field of a STRUCT, a value of an enum.
struct Declaration {
  std::string block;  // "VAR_INPUT", "VAR CONSTANT", "VAR_GLOBAL RETAIN", "STRUCT", "ENUM"
  std::string name;
  std::string type_key;    // "ARRAY [ 1 .. 3 ] OF INT"; for an enum value ""
  std::string value_key;   // the initial value (or the enum value), "" without one
  std::string other_key;   // AT address and constructor arguments
  std::string attributes;  // the pragmas written before it, e.g. "{attribute 'hide'}"
  std::string comment;     // comments around it (only with ReadOptions::comments)
  std::string text;        // "nState : INT := 5" as laid out by the formatter
};

// The object itself or one of its members (method, property, accessor, action, transition).
struct Part {
  std::string name;             // "" for the object itself; "M_Start", "P_Speed", "P_Speed.GET", "A_Reset"
  std::string kind;             // "METHOD", "PROPERTY", "GET", "SET", "ACTION", "TRANSITION"; the object's kind
  std::string header_key;       // the declaration outside its VAR blocks (name, return type, EXTENDS)
  std::string declaration_key;  // the whole declaration (header, blocks and declarations)
  std::string declaration_text;
  std::vector<Declaration> declarations;
  bool has_body = false;
  std::string body_key;
  std::string body_text;
};

struct Object {
  // "PROGRAM", "FUNCTION_BLOCK", "FUNCTION", "INTERFACE", "CLASS", "TYPE", "GVL", "CONFIGURATION"
  std::string kind;
  std::string name;
  std::string path;         // the file it was read from
  std::vector<Part> parts;  // parts[0] is the object itself, then its members in file order

  // Which names share a namespace: POUs and interfaces ("pou"), types ("type"), GVLs ("gvl").
  std::string_view name_space() const;
  // Everything but the object's own name (written as "\x01" wherever the code says it): two
  // objects with equal content keys are one object renamed.
  std::string content_key() const;
};

struct FileObjects {
  std::string path;
  std::vector<Object> objects;
  // Why the file (or part of it) could not be read: "malformed XML at line 3: ...", "binary file".
  std::vector<std::string> errors;
  // What was left out on purpose: "FB_Lamp.Ladder: LD implementation is graphical; not read as text".
  std::vector<std::string> notes;
};

struct ReadOptions {
  bool comments = false;  // comments count as content
};

// Never throws on any input; what cannot be read is in `errors`.
FileObjects read_objects(std::string_view path, std::string_view bytes, const ReadOptions& options = {});

// The ST text of any PLC source file: a vendor container's declarations and bodies in file
// order without the XML around them, laid out by `rung fmt` (as read when it does not format).
struct TextView {
  std::string text;
  std::vector<std::string> errors;  // as FileObjects::errors
  std::vector<std::string> notes;
};
TextView text_view(std::string_view path, std::string_view bytes);

// Whether a path names a file rung reads as PLC source (by extension; .xml files only when
// `bytes` is given and holds a PLCopen project).
bool is_plc_source_path(std::string_view path, std::string_view bytes = {});

}  // namespace rung::vcs
