// Three-way merges of PLC source files, for git's merge driver (`rung merge-file %O %A %B %P`).
//
// A file is split into units that have an identity in every version, and the units are merged
// by identity, so that independent changes to different units never conflict, whatever their
// position in the file:
//  - plain ST: the top-level objects (POU, member in the object shape, TYPE block, VAR_GLOBAL
//    block, CONFIGURATION), keyed by kind and name (a VAR_GLOBAL block by its section,
//    qualifiers and place), each with the comments before it; a POU deleted on one side while
//    a member written after it changed on the other stays, in the member's conflict;
//  - TwinCAT XML and PLCopen XML: the element tree, elements keyed by tag and Name (siblings
//    sharing a Name told apart by their first child); attributes merged one by one (both sides
//    changing a PLCopen attribute, which holds code there, is a conflict kept as ours; other
//    attributes are the tool's metadata: ours); the one child of a PLCopen type, value or body
//    chosen differently on both sides is a conflict kept as ours; the ST text inside
//    (declarations and bodies) merged line by line; TwinCAT's LineIds taken from our side
//    (TwinCAT recomputes them); ids kept unique;
//  - CODESYS .EXP: the exported objects, keyed by kind and name, each from its own
//    "(* @NESTEDCOMMENTS" marker line.
// Inside one unit changed on both sides the text is merged line by line (diff3); where both
// changed the same lines differently the result holds standard conflict markers around just
// those lines. A file whose units cannot be identified (syntax errors, duplicate names) is merged
// line by line as a whole. Conflicts of XML elements and attributes cannot be marked inside the
// XML: they keep one side and say so in a note.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rung::vcs {

struct MergeLabels {
  std::string ours = "ours";
  std::string theirs = "theirs";
};

struct MergeResult {
  std::string text;                // the merged file (bytes, in our side's encoding)
  size_t conflicts = 0;            // conflict regions written with markers (or kept as ours, see notes)
  std::vector<std::string> notes;  // "FB_Motor.M_Start: changed here, deleted there: kept the change"
  std::string error;               // set when the inputs cannot be merged at all (text is ours)
};

// Line-based three-way merge of texts (diff3): changes of one side apply; changes of both sides
// to the same base lines apply when equal, else become a conflict region.
MergeResult merge_lines(std::string_view base, std::string_view ours, std::string_view theirs,
                        const MergeLabels& labels = {});

// Merges three versions of the file `path` (its name decides the kind, as for `rung diff`).
MergeResult merge_file(std::string_view path, std::string_view base, std::string_view ours, std::string_view theirs,
                       const MergeLabels& labels = {});

}  // namespace rung::vcs
