// Comments without nesting. rung's grammar nests (* *) comments, as CODESYS V3 and TwinCAT do;
// CODESYS 2.3 objects exported with @NESTEDCOMMENTS := 'No', and MATIEC/Beremiz code, close a
// comment at its first '*)'. A '(*' inside such a comment must then not open a nested one.
#pragma once

#include <cstddef>
#include <string>

namespace rung::source {

// Blanks the '(' of every '(*' that stands inside a (* *) comment in text[begin, end), so the
// nesting grammar reads the comments flat. Same length: offsets do not move. Strings and
// // and /* */ comments are respected. Returns how many bytes were blanked.
size_t read_comments_flat(std::string& text, size_t begin, size_t end);

}  // namespace rung::source
