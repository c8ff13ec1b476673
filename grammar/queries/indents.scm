; Indentation for IEC 61131-3 (nvim-treesitter semantics:
; @indent.begin indents the lines inside a node, @indent.branch puts a line
; that starts with the captured node back at the level of the construct,
; @indent.end closes the block so that the line after it is not indented).
; Helix uses grammar/queries/helix/indents.scm instead.
;
; Layout this produces (the usual CODESYS / TwinCAT style):
;
;   FUNCTION_BLOCK FB_A          <- POU keywords, VAR blocks and the body
;   VAR_INPUT                       stay in column 0
;       x : INT;                 <- declarations: one level
;   END_VAR
;   IF x > 0 THEN
;       y := 1;                  <- statement bodies: one level
;   ELSIF x < 0 THEN
;       y := -1;
;   ELSE
;       y := 0;
;   END_IF
;   CASE y OF
;       1:
;           z := 2;              <- case element bodies: one more level
;   ELSE
;       z := 0;
;   END_CASE
;   END_FUNCTION_BLOCK
;
; To indent the contents of POUs as well, add their nodes
; (program_declaration, function_declaration, function_block_declaration,
; method_declaration, ...) to the @indent.begin list below.

[
  ; declarations
  (var_block)
  (struct_type)
  (union_type)
  (enum_type)
  (property_accessor)
  ; statements
  (if_statement)
  (case_statement)
  (case_element)
  (for_statement)
  (while_statement)
  (repeat_statement)
  (try_statement)
  ; multi-line calls and initialisers
  (argument_list)
  (struct_initializer)
  (array_initializer)
  (parenthesized_expression)
  ; SFC and configuration
  (sfc_step)
  (sfc_transition)
  (configuration_declaration)
  (resource_declaration)
] @indent.begin

; TYPE ST_X :
; STRUCT              <- STRUCT, UNION and the ( of an enumeration stay at
;     a : INT;           the level of the TYPE line
; END_STRUCT
(struct_type
  "STRUCT" @indent.branch)

(union_type
  "UNION" @indent.branch)

(enum_type
  "(" @indent.branch)

; Keywords that continue a construct at its own level
[
  "THEN"
  "ELSIF"
  "ELSE"
  "UNTIL"
  "DO"
  "__CATCH"
  "__FINALLY"
] @indent.branch

; Keywords and brackets that close a construct
[
  "END_VAR"
  "END_STRUCT"
  "END_UNION"
  "END_GET"
  "END_SET"
  "END_IF"
  "END_CASE"
  "END_FOR"
  "END_WHILE"
  "END_REPEAT"
  "__ENDTRY"
  "END_STEP"
  "END_TRANSITION"
  "END_RESOURCE"
  "END_CONFIGURATION"
] @indent.branch @indent.end

[
  ")"
  "]"
] @indent.branch @indent.end

; END_IF; END_VAR; ...: a semicolon after the closing keyword also ends the
; block, so the next line is not indented.
(var_block
  ";" @indent.end)

(struct_type
  ";" @indent.end)

(union_type
  ";" @indent.end)

(enum_type
  ";" @indent.end)

(if_statement
  ";" @indent.end)

(case_statement
  ";" @indent.end)

(for_statement
  ";" @indent.end)

(while_statement
  ";" @indent.end)

(repeat_statement
  ";" @indent.end)

(try_statement
  ";" @indent.end)

(sfc_step
  ";" @indent.end)

(sfc_transition
  ";" @indent.end)

; Block comments keep the indentation the user gave them.
(comment) @indent.auto
