; Code navigation tags for IEC 61131-3 (tree-sitter tags: `tree-sitter tags`,
; GitHub code navigation). @name is the symbol, @definition.* / @reference.*
; the whole item. Helix uses grammar/queries/helix/tags.scm instead.

; POUs
(function_declaration
  name: (identifier) @name) @definition.function

(function_block_declaration
  name: (identifier) @name) @definition.class

(class_declaration
  name: (identifier) @name) @definition.class

(program_declaration
  name: (identifier) @name) @definition.module

(interface_declaration
  name: (identifier) @name) @definition.interface

(method_declaration
  name: (identifier) @name) @definition.method

(action_declaration
  name: (identifier) @name) @definition.method

(property_declaration
  name: (identifier) @name) @definition.method

(namespace_declaration
  name: (qualified_name) @name) @definition.module

(configuration_declaration
  name: (identifier) @name) @definition.module

; Data types
(struct_type
  name: (identifier) @name) @definition.type

(union_type
  name: (identifier) @name) @definition.type

(enum_type
  name: (identifier) @name) @definition.type

(alias_type
  name: (identifier) @name) @definition.type

; Constants: enumeration values and VAR ... CONSTANT declarations
(enum_value
  name: (identifier) @name) @definition.constant

(var_block
  (var_qualifier
    "CONSTANT")
  (var_declaration
    name: (identifier) @name) @definition.constant)

; Calls: functions, function block instances, methods
(call_expression
  function: (identifier) @name) @reference.call

(call_expression
  function: (member_expression
    member: (identifier) @name)) @reference.call

; Uses of types in EXTENDS / IMPLEMENTS and declarations
(extends_clause
  (type_name
    (identifier) @name .)) @reference.class

(implements_clause
  (type_name
    (identifier) @name .)) @reference.implementation

(var_declaration
  type: (type_name
    (identifier) @name .)) @reference.type
