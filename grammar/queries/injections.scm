; Language injections for IEC 61131-3.
;
; Comments are handed to the `comment` parser (tree-sitter-comment), which
; highlights TODO:, FIXME:, NOTE: and similar tags when it is installed
; (Neovim: `:TSInstall comment`; Helix ships it). Without it nothing changes.
((comment) @injection.content
  (#set! injection.language "comment"))
