// What vcs::merge_file must guarantee for any three versions of a file, as one check shared by
// the merge property test (tests/vcs/merge_fuzz_test.cpp) and the libFuzzer target
// (fuzz/merge_fuzzer.cpp). Issue 17: the merge never loses a side's change silently and never
// writes an unreadable file.
//
// The properties, on the result of merge_file(path, base, ours, theirs):
//  - merging the same versions again gives the same bytes; a merge that fails (malformed
//    input) leaves ours as it was;
//  - an XML container comes out well-formed, with every GUID Id unique, conflicts or not;
//  - every reported conflict is visible: the file holds one marked region per conflict, except
//    the XML element conflicts the merge resolves to one side and names in a "kept" note; a
//    clean merge holds no markers;
//  - a clean merge reads back without container errors when the three versions do;
//  - when the three versions parse without errors and the merge went by objects (not the whole
//    file line by line, as when a version holds none): the file read with each conflict region
//    resolved to our side (and again to theirs) has every change that side made alone,
//    compared through the object model. An object only one side changed (added, deleted) is
//    that side's version; one neither changed is the base's; in an object both changed, the
//    same for each member; in a member both changed, for each field (block, type, initial
//    value, AT/arguments, attributes) of each declaration. A clean merge has no regions, so
//    this holds for the merged file itself. What keeps the check true to any correct merge:
//    a thing one side moved and the other changed counts as changed on both sides (to diff3 a
//    move is a deletion and an insertion, and either can undo the other side's change); with
//    conflicts, a thing neither side changed need only be in one resolution (the insertion of
//    a moved line may be what conflicts); a thing one side added while removing one the other
//    side changed may be a rename the merge followed, carrying the other change along: for it
//    only its presence is checked. The resolved merge must parse too, or the objects are not
//    compared: their reading of broken code is error recovery's guess, and a line merge can
//    make code that does not parse of two edits of one object (as any textual merge can) or,
//    with conflicts, of changes the model does not see (a moved END_VAR);
//  - with the same preconditions, a clean merge parses unless an object was changed on both
//    sides.
// The object comparisons trust the object model to read each version as its text says: code
// the parser takes without an error but in an unexpected way (a declaration line before the
// first VAR block of a TwinCAT POU reads as the start of its body) can make a correct merge
// look wrong. `rung textconv` of the three versions tells such a case from a merge bug.
// Inputs that already hold conflict marker lines ("<<<<<<<", "=======", ">>>>>>>") cannot be
// told apart from the merge's own: for them only the first two properties are checked.
#pragma once

#include <string>
#include <string_view>

#include "vcs/merge.hpp"

namespace rung::test {

struct MergeCheck {
  vcs::MergeResult merge;         // what merge_file returned
  std::string violation;          // "" when every property holds; else the ones that fail, for people
  bool objects_compared = false;  // the versions were compared through the object model (see above)
};

MergeCheck check_merge(std::string_view path, std::string_view base, std::string_view ours, std::string_view theirs);

// The properties above but the first one's determinism, of `merge` as the result of merging
// the versions with the default labels: the check without the merge, so that it can be shown
// to catch what a broken merge would return. "" when every property holds.
std::string merge_violations(std::string_view path, std::string_view base, std::string_view ours,
                             std::string_view theirs, const vcs::MergeResult& merge, bool* objects_compared = nullptr);

// Whether `rung parse` finds no error in the file (named `path`): no syntax, container or
// encoding error.
bool parses_cleanly(std::string_view path, std::string_view bytes);

}  // namespace rung::test
