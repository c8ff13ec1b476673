; Scopes, definitions and references for IEC 61131-3 (nvim-treesitter names).
; Helix uses grammar/queries/helix/locals.scm instead.
;
; A POU's own name is defined in the scope around it (definition.*.scope
; "parent"), its variables and parameters inside it.

; ---------------------------------------------------------------------------
; Scopes
; ---------------------------------------------------------------------------

[
  (program_declaration)
  (function_declaration)
  (function_block_declaration)
  (class_declaration)
  (interface_declaration)
  (method_declaration)
  (property_declaration)
  (property_accessor)
  (action_declaration)
  (namespace_declaration)
  (configuration_declaration)
  (resource_declaration)
  (sfc_transition)
] @local.scope

; ---------------------------------------------------------------------------
; Definitions: POUs and types
; ---------------------------------------------------------------------------

((function_declaration
  name: (identifier) @local.definition.function)
  (#set! definition.function.scope "parent"))

((method_declaration
  name: (identifier) @local.definition.method)
  (#set! definition.method.scope "parent"))

((action_declaration
  name: (identifier) @local.definition.method)
  (#set! definition.method.scope "parent"))

((property_declaration
  name: (identifier) @local.definition.field)
  (#set! definition.field.scope "parent"))

((program_declaration
  name: (identifier) @local.definition.type)
  (#set! definition.type.scope "parent"))

((function_block_declaration
  name: (identifier) @local.definition.type)
  (#set! definition.type.scope "parent"))

((class_declaration
  name: (identifier) @local.definition.type)
  (#set! definition.type.scope "parent"))

((interface_declaration
  name: (identifier) @local.definition.type)
  (#set! definition.type.scope "parent"))

((namespace_declaration
  name: (qualified_name) @local.definition.namespace)
  (#set! definition.namespace.scope "parent"))

((configuration_declaration
  name: (identifier) @local.definition.namespace)
  (#set! definition.namespace.scope "parent"))

((resource_declaration
  name: (identifier) @local.definition.namespace)
  (#set! definition.namespace.scope "parent"))

(struct_type
  name: (identifier) @local.definition.type)

(union_type
  name: (identifier) @local.definition.type)

(alias_type
  name: (identifier) @local.definition.type)

(enum_type
  name: (identifier) @local.definition.enum)

(enum_value
  name: (identifier) @local.definition.constant)

(generic_parameter
  name: (identifier) @local.definition.type)

(using_directive
  (qualified_name) @local.definition.import)

; ---------------------------------------------------------------------------
; Definitions: variables, parameters, fields
; ---------------------------------------------------------------------------

(var_block
  (var_declaration
    name: (identifier) @local.definition.var))

(var_block
  kind: [
    "VAR_INPUT"
    "VAR_OUTPUT"
    "VAR_IN_OUT"
  ]
  (var_declaration
    name: (identifier) @local.definition.parameter))

(var_block
  (var_qualifier
    "CONSTANT")
  (var_declaration
    name: (identifier) @local.definition.constant))

(struct_type
  (var_declaration
    name: (identifier) @local.definition.field))

(union_type
  (var_declaration
    name: (identifier) @local.definition.field))

; Declaration lines written without their VAR block (code fragments)
(source_file
  (var_declaration
    name: (identifier) @local.definition.var))

(catch_clause
  exception: (identifier) @local.definition.var)

(task_configuration
  name: (identifier) @local.definition.var)

(program_configuration
  name: (identifier) @local.definition.var)

; Jump labels and SFC steps
(label
  name: (identifier) @local.definition)

(il_label
  name: (identifier) @local.definition)

(sfc_step
  name: (identifier) @local.definition)

; ---------------------------------------------------------------------------
; References
; ---------------------------------------------------------------------------

(identifier) @local.reference
