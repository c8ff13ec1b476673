; Scopes, definitions and references for IEC 61131-3 in Helix. A reference that
; resolves to a definition takes the highlight named by the definition's
; suffix (see the Helix book, "Adding locals queries").

[
  (program_declaration)
  (function_declaration)
  (function_block_declaration)
  (class_declaration)
  (interface_declaration)
  (method_declaration)
  (property_declaration)
  (action_declaration)
] @local.scope

(var_block
  (var_declaration
    name: (identifier) @local.definition.variable))

(var_block
  kind: [
    "VAR_INPUT"
    "VAR_OUTPUT"
    "VAR_IN_OUT"
  ]
  (var_declaration
    name: (identifier) @local.definition.variable.parameter))

(var_block
  (var_qualifier
    "CONSTANT")
  (var_declaration
    name: (identifier) @local.definition.constant))

(enum_value
  name: (identifier) @local.definition.constant)

(identifier) @local.reference

; Not references to a variable: member names, parameter names in calls, field
; names in initialisers, called names, type names and typed literals.
(member_expression
  member: (identifier) @_member)

(argument
  name: (identifier) @_argument)

(output_argument
  name: (identifier) @_argument)

(field_initializer
  name: (identifier) @_field)

(call_expression
  function: (identifier) @_call)

(type_name
  (identifier) @_type)

(typed_literal
  (identifier) @_literal)
