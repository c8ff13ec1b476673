; Indentation for IEC 61131-3 in Helix (@indent / @outdent, see the Helix book,
; "Adding indent queries"). Same layout as grammar/queries/indents.scm: POU
; keywords, VAR blocks and POU bodies stay in column 0; declarations inside
; VAR ... END_VAR, TYPE bodies and the bodies of IF, CASE, FOR, WHILE, REPEAT
; and __TRY get one level, case element bodies one more.

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
] @indent

; STRUCT, UNION and the ( of an enumeration stay at the level of the TYPE line.
(struct_type
  "STRUCT" @outdent)

(union_type
  "UNION" @outdent)

(enum_type
  "(" @outdent)

[
  "THEN"
  "ELSIF"
  "ELSE"
  "UNTIL"
  "DO"
  "__CATCH"
  "__FINALLY"
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
  ")"
  "]"
] @outdent
