// Turning the bytes of a source file into UTF-8 text.
//
// PLC sources come in whatever the vendor tool wrote: UTF-8 with or without a BOM
// (TwinCAT), cp1252 (CODESYS V2, OSCAT), sometimes UTF-16 (exports from Windows
// tools). Everything after this step works on UTF-8 only; `encode` writes text
// back in the file's own encoding so the formatter does not change it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rung::source {

enum class Encoding { Utf8, Cp1252, Utf16Le, Utf16Be };

// "UTF-8", "cp1252", "UTF-16LE", "UTF-16BE": for messages and `--format json`.
std::string_view encoding_name(Encoding encoding);

struct DecodeIssue {
  uint32_t offset;  // byte offset in the UTF-8 output
  std::string message;
};

struct DecodedText {
  std::string utf8;  // empty when is_binary: binary files are not decoded
  Encoding encoding = Encoding::Utf8;
  bool had_bom = false;
  bool is_binary = false;
  std::vector<DecodeIssue> issues;  // at most max_decode_issues + 1 summary entry
};

// Issues beyond this count are folded into one summary issue, so a damaged
// 100 MB file cannot produce millions of diagnostics.
inline constexpr size_t max_decode_issues = 100;

// Never fails and runs in linear time. Rules, in order:
//  1. a UTF-8 / UTF-16 BOM decides the encoding (the BOM is not part of the text);
//  2. BOM-less UTF-16 is recognised by its pattern of zero bytes;
//  3. NUL bytes or many control characters in the first 8 KiB: binary;
//  4. valid UTF-8 is taken as is;
//  5. text that is mostly valid UTF-8 with a few bad bytes stays UTF-8, each bad
//     sequence becomes U+FFFD with an issue;
//  6. anything else is cp1252 (undefined bytes become U+FFFD with an issue).
DecodedText decode(std::string_view bytes);

// True when the sample (the first 8 KiB of a file) looks like binary data.
bool looks_binary(std::string_view sample);

}  // namespace rung::source
