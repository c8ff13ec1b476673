#!/usr/bin/env bash
# Regenerates tests/grammar/highlights_golden.expected from tests/grammar/highlights_golden.st.
#
# Usage (from anywhere in the checkout):
#   scripts/grammar/update-highlight-golden.sh           rewrite the expected file
#   scripts/grammar/update-highlight-golden.sh --check   compare only; exit 1 on a difference
#
# Needs the tree-sitter CLI (scripts/regen-grammar installs the pinned one into ~/.cargo/bin)
# and python3. The CLI compiles grammar/src on first use, so the captures are those of the
# grammar as it is in the working tree.
#
# It runs `tree-sitter query --captures grammar/queries/highlights.scm <sample>`, i.e. the
# captures in the order a query cursor yields them with ts_query_cursor_next_capture (sorted
# by start position; for one node, by pattern order), with the text predicates (#match?,
# #any-of?, #eq?) already applied. Each capture becomes one line:
#
#   ROW:COL-ROW:COL CAPTURE "TEXT"
#
# ROW and COL are tree-sitter points: 0-based row, 0-based byte column (TSPoint, exactly what
# ts_node_start_point / ts_node_end_point return). TEXT is the source bytes of the captured
# node, with backslash, double quote, newline, carriage return and tab written as
# \\ \" \n \r \t. The file has no header or comment lines.
#
# Review the diff of the expected file after changing highlights.scm or the grammar: every
# changed line is a changed highlight.
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
sample="$root/tests/grammar/highlights_golden.st"
expected="$root/tests/grammar/highlights_golden.expected"
query="$root/grammar/queries/highlights.scm"

ts="$(command -v tree-sitter || true)"
[ -z "$ts" ] && [ -x "$HOME/.cargo/bin/tree-sitter" ] && ts="$HOME/.cargo/bin/tree-sitter"
[ -z "$ts" ] && { echo "update-highlight-golden: tree-sitter CLI not found (see scripts/regen-grammar)" >&2; exit 2; }
command -v python3 >/dev/null 2>&1 || { echo "update-highlight-golden: needs python3" >&2; exit 2; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# The CLI finds the grammar through grammar/tree-sitter.json in the working directory.
(cd "$root/grammar" && "$ts" query --captures "$query" "$sample") >"$tmp/raw" 2>"$tmp/err" || {
  cat "$tmp/err" >&2
  echo "update-highlight-golden: tree-sitter query failed" >&2
  exit 1
}

python3 - "$sample" "$tmp/raw" >"$tmp/expected" <<'PY'
import re
import sys

source = open(sys.argv[1], "rb").read()
lines = source.split(b"\n")
# Byte offset of the start of each row.
row_start = []
offset = 0
for line in lines:
    row_start.append(offset)
    offset += len(line) + 1

record = re.compile(
    r"^\s+pattern:\s*\d+, capture: \d+ - ([^,]+), start: \((\d+), (\d+)\), end: \((\d+), (\d+)\), text: `")

def escape(data):
    text = data.decode("utf-8")
    return (text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
            .replace("\r", "\\r").replace("\t", "\\t"))

count = 0
for raw_line in open(sys.argv[2], encoding="utf-8"):
    m = record.match(raw_line)
    if not m:
        continue  # file name line, or a continuation line of a multi-line text
    name = m.group(1)
    sr, sc, er, ec = (int(g) for g in m.group(2, 3, 4, 5))
    text = source[row_start[sr] + sc:row_start[er] + ec]
    print(f'{sr}:{sc}-{er}:{ec} {name} "{escape(text)}"')
    count += 1

if count == 0:
    sys.exit("update-highlight-golden: no captures parsed from the CLI output")
PY

if [ "${1:-}" = "--check" ]; then
  if diff -u "$expected" "$tmp/expected"; then
    echo "update-highlight-golden: $(wc -l <"$expected") captures match"
    exit 0
  fi
  echo "update-highlight-golden: captures differ; run scripts/grammar/update-highlight-golden.sh" >&2
  exit 1
fi

cp "$tmp/expected" "$expected"
echo "update-highlight-golden: wrote $(wc -l <"$expected") captures to ${expected#"$root"/}"
