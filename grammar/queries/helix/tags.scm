; Symbols for Helix's symbol pickers (see the Helix book, "Adding tags
; queries"): only the definition kinds Helix lists. Methods, actions and
; properties are shown as functions.

(function_declaration
  name: (identifier) @name) @definition.function

(method_declaration
  name: (identifier) @name) @definition.function

(action_declaration
  name: (identifier) @name) @definition.function

(property_declaration
  name: (identifier) @name) @definition.function

(function_block_declaration
  name: (identifier) @name) @definition.class

(class_declaration
  name: (identifier) @name) @definition.class

(program_declaration
  name: (identifier) @name) @definition.module

(namespace_declaration
  name: (qualified_name) @name) @definition.module

(configuration_declaration
  name: (identifier) @name) @definition.module

(interface_declaration
  name: (identifier) @name) @definition.interface

(struct_type
  name: (identifier) @name) @definition.struct

(union_type
  name: (identifier) @name) @definition.type

(enum_type
  name: (identifier) @name) @definition.type

(alias_type
  name: (identifier) @name) @definition.type

(enum_value
  name: (identifier) @name) @definition.constant

(var_block
  (var_qualifier
    "CONSTANT")
  (var_declaration
    name: (identifier) @name) @definition.constant)
