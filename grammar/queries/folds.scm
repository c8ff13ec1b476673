; Folding for IEC 61131-3 (nvim-treesitter: @fold). Only nodes that span more
; than one line fold.
;
; {region ...} ... {endregion} cannot fold: the grammar makes each pragma its
; own node, so there is no node that spans the region.

[
  ; POUs and their members
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
  ; declarations
  (var_block)
  (type_declaration)
  (struct_type)
  (union_type)
  (enum_type)
  ; statements
  (if_statement)
  (elsif_clause)
  (else_clause)
  (case_statement)
  (case_element)
  (for_statement)
  (while_statement)
  (repeat_statement)
  (try_statement)
  (catch_clause)
  (finally_clause)
  ; multi-line calls and initialisers
  (argument_list)
  (struct_initializer)
  (array_initializer)
  ; SFC and configuration
  (sfc_step)
  (sfc_transition)
  (configuration_declaration)
  (resource_declaration)
  ; block comments
  (comment)
] @fold
