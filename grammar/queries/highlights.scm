; Syntax highlighting for IEC 61131-3 (tree-sitter language `iec61131`).
;
; Capture names follow nvim-treesitter. Later patterns take precedence over
; earlier ones (Neovim, Helix 25.07+ and the tree-sitter CLI all agree), so the
; file goes from general to specific. grammar/queries/helix/highlights.scm is
; this file with Helix scope names; keep both in step (see its header).
;
; ST is case-insensitive. Keywords are anonymous nodes with an upper-case name
; whatever the spelling in the source, so "IF" matches `if` and `If` too.
; Names matched by text (built-in types and functions) are listed in upper,
; lower and capitalised spelling; regexes use only ^ $ [] * so that they mean
; the same in Vim regex (Neovim) and Rust regex (Helix, tree-sitter CLI).

; ---------------------------------------------------------------------------
; Identifiers (fallback)
; ---------------------------------------------------------------------------

(identifier) @variable

; ---------------------------------------------------------------------------
; Keywords
; ---------------------------------------------------------------------------

[
  "VAR"
  "VAR_INPUT"
  "VAR_OUTPUT"
  "VAR_IN_OUT"
  "VAR_GLOBAL"
  "VAR_EXTERNAL"
  "VAR_TEMP"
  "VAR_STAT"
  "VAR_INST"
  "VAR_CONFIG"
  "VAR_ACCESS"
  "END_VAR"
  "AT"
  "EXTENDS"
  "IMPLEMENTS"
  "CONFIGURATION"
  "END_CONFIGURATION"
  "RESOURCE"
  "END_RESOURCE"
  "ON"
  "TASK"
  "WITH"
  "INITIAL_STEP"
  "STEP"
  "END_STEP"
  "TRANSITION"
  "END_TRANSITION"
  "FROM"
  "NAMESPACE"
  "END_NAMESPACE"
  "JMP"
  "R_EDGE"
  "F_EDGE"
] @keyword

; TO appears in FOR loops, POINTER TO, REFERENCE TO and SFC transitions.
(sfc_transition "TO" @keyword)

[
  "PROGRAM"
  "END_PROGRAM"
  "FUNCTION"
  "END_FUNCTION"
  "FUNCTION_BLOCK"
  "END_FUNCTION_BLOCK"
  "METHOD"
  "END_METHOD"
  "PROPERTY"
  "PROPERTY_GET"
  "PROPERTY_SET"
  "END_PROPERTY"
  "GET"
  "END_GET"
  "SET"
  "END_SET"
  "ACTION"
  "END_ACTION"
] @keyword.function

[
  "TYPE"
  "END_TYPE"
  "STRUCT"
  "END_STRUCT"
  "UNION"
  "END_UNION"
  "CLASS"
  "END_CLASS"
  "INTERFACE"
  "END_INTERFACE"
  "ARRAY"
  "POINTER"
  "REFERENCE"
  "REF_TO"
] @keyword.type

(array_type "OF" @keyword.type)
(pointer_type "TO" @keyword.type)
(reference_type "TO" @keyword.type)

[
  "CONSTANT"
  "RETAIN"
  "PERSISTENT"
  "NON_RETAIN"
  "PUBLIC"
  "PRIVATE"
  "PROTECTED"
  "INTERNAL"
  "ABSTRACT"
  "FINAL"
] @keyword.modifier

"USING" @keyword.import

[
  "IF"
  "THEN"
  "ELSIF"
  "ELSE"
  "END_IF"
  "CASE"
  "END_CASE"
] @keyword.conditional

(case_statement "OF" @keyword.conditional)

[
  "FOR"
  "BY"
  "DO"
  "END_FOR"
  "WHILE"
  "END_WHILE"
  "REPEAT"
  "UNTIL"
  "END_REPEAT"
  "EXIT"
  "CONTINUE"
] @keyword.repeat

(for_statement "TO" @keyword.repeat)

"RETURN" @keyword.return

[
  "__TRY"
  "__CATCH"
  "__FINALLY"
  "__ENDTRY"
] @keyword.exception

[
  "AND"
  "AND_THEN"
  "OR"
  "OR_ELSE"
  "XOR"
  "NOT"
  "MOD"
] @keyword.operator

; ---------------------------------------------------------------------------
; Operators and punctuation
; ---------------------------------------------------------------------------

[
  ":="
  "=>"
  "?="
  "S="
  "R="
  "REF="
  "="
  "<>"
  "<"
  ">"
  "<="
  ">="
  "+"
  "-"
  "*"
  "/"
  "**"
  "&"
  "^"
  ".."
] @operator

[
  "("
  ")"
  "["
  "]"
] @punctuation.bracket

(generic_parameters
  [
    "<"
    ">"
  ] @punctuation.bracket)

[
  ","
  ";"
  ":"
  "."
  "|"
] @punctuation.delimiter

(typed_literal "#" @punctuation.special)

(array_type (wildcard) @operator)

; ---------------------------------------------------------------------------
; Types
; ---------------------------------------------------------------------------

; A qualified type name: the last part is the type, the parts before it are
; namespaces or libraries.
(type_name
  (identifier) @module
  .
  ".")

(type_name
  (identifier) @type .)

((type_name
  .
  (identifier) @type.builtin .)
  (#any-of? @type.builtin
  "BOOL" "bool" "Bool" "BYTE" "byte" "Byte" "WORD" "word" "Word" "DWORD" "dword" "Dword"
  "LWORD" "lword" "Lword" "SINT" "sint" "Sint" "USINT" "usint" "Usint" "INT" "int" "Int" "UINT"
  "uint" "Uint" "DINT" "dint" "Dint" "UDINT" "udint" "Udint" "LINT" "lint" "Lint" "ULINT"
  "ulint" "Ulint" "REAL" "real" "Real" "LREAL" "lreal" "Lreal" "TIME" "time" "Time" "LTIME"
  "ltime" "Ltime" "DATE" "date" "Date" "LDATE" "ldate" "Ldate" "TIME_OF_DAY" "time_of_day"
  "Time_of_day" "TOD" "tod" "Tod" "LTIME_OF_DAY" "ltime_of_day" "Ltime_of_day" "LTOD" "ltod"
  "Ltod" "DATE_AND_TIME" "date_and_time" "Date_and_time" "DT" "dt" "Dt" "LDATE_AND_TIME"
  "ldate_and_time" "Ldate_and_time" "LDT" "ldt" "Ldt" "STRING" "string" "String" "WSTRING"
  "wstring" "Wstring" "CHAR" "char" "Char" "WCHAR" "wchar" "Wchar" "BIT" "bit" "Bit" "XINT"
  "xint" "Xint" "UXINT" "uxint" "Uxint" "XWORD" "xword" "Xword" "__XINT" "__xint" "__UXINT"
  "__uxint" "__XWORD" "__xword" "PVOID" "pvoid" "Pvoid" "ANY" "any" "Any" "ANY_DERIVED"
  "any_derived" "Any_derived" "ANY_ELEMENTARY" "any_elementary" "Any_elementary"
  "ANY_MAGNITUDE" "any_magnitude" "Any_magnitude" "ANY_NUM" "any_num" "Any_num" "ANY_REAL"
  "any_real" "Any_real" "ANY_INT" "any_int" "Any_int" "ANY_SIGNED" "any_signed" "Any_signed"
  "ANY_UNSIGNED" "any_unsigned" "Any_unsigned" "ANY_DURATION" "any_duration" "Any_duration"
  "ANY_BIT" "any_bit" "Any_bit" "ANY_CHARS" "any_chars" "Any_chars" "ANY_STRING" "any_string"
  "Any_string" "ANY_CHAR" "any_char" "Any_char" "ANY_DATE" "any_date" "Any_date"
  ; standard function blocks (IEC 61131-3 timers, edges, counters, bistables)
  "TON" "ton" "Ton" "TOF" "tof" "Tof" "TP" "tp" "Tp" "TONR" "tonr" "Tonr" "R_TRIG" "r_trig"
  "R_trig" "F_TRIG" "f_trig" "F_trig" "CTU" "ctu" "Ctu" "CTD" "ctd" "Ctd" "CTUD" "ctud" "Ctud"
  "SR" "sr" "Sr" "RS" "rs" "Rs"))

(string_type
  [
    "STRING"
    "WSTRING"
  ] @type.builtin)

; INT#5, E_Mode#Auto: the prefix names a type.
(typed_literal
  type: (identifier) @type)

((typed_literal
  type: (identifier) @type.builtin)
  (#any-of? @type.builtin
  "BOOL" "bool" "Bool" "BYTE" "byte" "Byte" "WORD" "word" "Word" "DWORD" "dword" "Dword"
  "LWORD" "lword" "Lword" "SINT" "sint" "Sint" "USINT" "usint" "Usint" "INT" "int" "Int" "UINT"
  "uint" "Uint" "DINT" "dint" "Dint" "UDINT" "udint" "Udint" "LINT" "lint" "Lint" "ULINT"
  "ulint" "Ulint" "REAL" "real" "Real" "LREAL" "lreal" "Lreal" "STRING" "string" "String"
  "WSTRING" "wstring" "Wstring" "CHAR" "char" "Char" "WCHAR" "wchar" "Wchar"))

(typed_literal
  value: (identifier) @constant)

; Declarations of types
(struct_type
  name: (identifier) @type.definition)

(union_type
  name: (identifier) @type.definition)

(enum_type
  name: (identifier) @type.definition)

(alias_type
  name: (identifier) @type.definition)

(generic_parameter
  name: (identifier) @type.definition)

; Function blocks, classes, interfaces and programs are instantiable types.
(function_block_declaration
  name: (identifier) @type)

(class_declaration
  name: (identifier) @type)

(interface_declaration
  name: (identifier) @type)

(program_declaration
  name: (identifier) @type)

(program_configuration
  type: (type_name
    (identifier) @type))

; ---------------------------------------------------------------------------
; Modules (namespaces, configurations, resources)
; ---------------------------------------------------------------------------

(namespace_declaration
  name: (qualified_name
    (identifier) @module))

(using_directive
  (qualified_name
    (identifier) @module))

(configuration_declaration
  name: (identifier) @module)

(resource_declaration
  name: (identifier) @module)

(resource_declaration
  processor: (type_name
    (identifier) @type))

; ---------------------------------------------------------------------------
; Variables, parameters, members, constants
; ---------------------------------------------------------------------------

(var_block
  kind: [
    "VAR_INPUT"
    "VAR_OUTPUT"
    "VAR_IN_OUT"
  ]
  (var_declaration
    name: (identifier) @variable.parameter))

(var_block
  (var_qualifier
    "CONSTANT")
  (var_declaration
    name: (identifier) @constant))

(argument
  name: (identifier) @variable.parameter)

(output_argument
  name: (identifier) @variable.parameter)

(member_expression
  member: (identifier) @variable.member)

(struct_type
  (var_declaration
    name: (identifier) @variable.member))

(union_type
  (var_declaration
    name: (identifier) @variable.member))

(field_initializer
  name: (identifier) @variable.member)

(enum_value
  name: (identifier) @constant)

(property_declaration
  name: (identifier) @property)

(task_configuration
  name: (identifier) @variable)

(program_configuration
  name: (identifier) @variable)

((identifier) @variable.builtin
  (#any-of? @variable.builtin "THIS" "this" "This" "SUPER" "super" "Super"))

; Naming conventions of CODESYS and TwinCAT projects: E_Xxx.Value is an
; enumeration value, GVL_Xxx.name a variable of a global variable list.
((member_expression
  object: (identifier) @type
  member: (identifier) @constant)
  (#match? @type "^E_"))

((member_expression
  object: (identifier) @module)
  (#match? @module "^GVL"))

; ---------------------------------------------------------------------------
; Functions and methods
; ---------------------------------------------------------------------------

(function_declaration
  name: (identifier) @function)

(method_declaration
  name: (identifier) @function.method)

(action_declaration
  name: (identifier) @function.method)

(call_expression
  function: (identifier) @function.call)

(call_expression
  function: (member_expression
    member: (identifier) @function.method.call))

; Standard functions
((call_expression
  function: (identifier) @function.builtin)
  (#any-of? @function.builtin
  "ABS" "abs" "Abs" "SQRT" "sqrt" "Sqrt" "LN" "ln" "Ln" "LOG" "log" "Log" "EXP" "exp" "Exp"
  "EXPT" "expt" "Expt" "SIN" "sin" "Sin" "COS" "cos" "Cos" "TAN" "tan" "Tan" "ASIN" "asin"
  "Asin" "ACOS" "acos" "Acos" "ATAN" "atan" "Atan" "ATAN2" "atan2" "Atan2" "ADD" "add" "Add"
  "SUB" "sub" "Sub" "MUL" "mul" "Mul" "DIV" "div" "Div" "MOVE" "move" "Move" "SEL" "sel" "Sel"
  "MUX" "mux" "Mux" "MAX" "max" "Max" "MIN" "min" "Min" "LIMIT" "limit" "Limit" "SHL" "shl"
  "Shl" "SHR" "shr" "Shr" "ROL" "rol" "Rol" "ROR" "ror" "Ror" "LEN" "len" "Len" "LEFT" "left"
  "Left" "RIGHT" "right" "Right" "MID" "mid" "Mid" "CONCAT" "concat" "Concat" "INSERT" "insert"
  "Insert" "DELETE" "delete" "Delete" "REPLACE" "replace" "Replace" "FIND" "find" "Find" "GT"
  "gt" "Gt" "GE" "ge" "Ge" "EQ" "eq" "Eq" "LE" "le" "Le" "LT" "lt" "Lt" "NE" "ne" "Ne" "TRUNC"
  "trunc" "Trunc" "ADR" "adr" "Adr" "ADRINST" "adrinst" "Adrinst" "BITADR" "bitadr" "Bitadr"
  "SIZEOF" "sizeof" "Sizeof" "XSIZEOF" "xsizeof" "Xsizeof" "INDEXOF" "indexof" "Indexof"
  "LOWER_BOUND" "lower_bound" "Lower_bound" "UPPER_BOUND" "upper_bound" "Upper_bound" "__NEW"
  "__new" "__DELETE" "__delete" "__ISVALIDREF" "__isvalidref" "__QUERYINTERFACE"
  "__queryinterface" "__QUERYPOINTER" "__querypointer" "__VARINFO" "__varinfo"))

; Type conversions: INT_TO_REAL, real_to_dint, TO_LREAL, TRUNC_INT ...
((call_expression
  function: (identifier) @function.builtin)
  (#match? @function.builtin "^[A-Z][A-Z_]*_TO_[A-Z][A-Z_]*$"))

((call_expression
  function: (identifier) @function.builtin)
  (#match? @function.builtin "^[a-z][a-z_]*_to_[a-z][a-z_]*$"))

((call_expression
  function: (identifier) @function.builtin)
  (#match? @function.builtin "^TO_[A-Z][A-Z_]*$"))

((call_expression
  function: (identifier) @function.builtin)
  (#match? @function.builtin "^to_[a-z][a-z_]*$"))

((call_expression
  function: (identifier) @function.builtin)
  (#match? @function.builtin "^TRUNC_[A-Z][A-Z]*$"))

; Instruction List: the operator column
(il_instruction
  operator: (il_operator) @function.call)

((il_instruction
  operator: (il_operator) @keyword)
  (#any-of? @keyword
  "LD" "ld" "Ld" "LDN" "ldn" "Ldn" "ST" "st" "St" "STN" "stn" "Stn" "S" "s" "R" "r"
  "AND" "and" "And" "ANDN" "andn" "Andn" "OR" "or" "Or" "ORN" "orn" "Orn" "XOR" "xor" "Xor"
  "XORN" "xorn" "Xorn" "NOT" "not" "Not" "ADD" "add" "Add" "SUB" "sub" "Sub" "MUL" "mul" "Mul"
  "DIV" "div" "Div" "MOD" "mod" "Mod" "GT" "gt" "Gt" "GE" "ge" "Ge" "EQ" "eq" "Eq" "NE" "ne"
  "Ne" "LE" "le" "Le" "LT" "lt" "Lt" "CAL" "cal" "Cal" "CALC" "calc" "Calc" "CALCN" "calcn"
  "Calcn" "RET" "ret" "Ret" "RETC" "retc" "Retc" "RETCN" "retcn" "Retcn" "RETURN" "return"
  "Return"))

((il_instruction
  operator: (il_operator) @keyword.repeat
  operand: (identifier) @label)
  (#any-of? @keyword.repeat "JMP" "jmp" "Jmp" "JMPC" "jmpc" "Jmpc" "JMPCN" "jmpcn" "Jmpcn"))

; SFC
(sfc_step
  name: (identifier) @label)

(sfc_transition
  name: (identifier) @label)

; FROM S1 TO S2, FROM (S1, S2) TO S3: the step lists. (A field query such as
; `to: (identifier)` misses the names of a parenthesised list.)
(sfc_transition
  [
    "FROM"
    "TO"
    ","
  ]
  .
  (identifier) @label)

(sfc_action
  name: (identifier) @function.call)

(sfc_action
  qualifier: (identifier) @attribute)

; ---------------------------------------------------------------------------
; Labels
; ---------------------------------------------------------------------------

(label
  name: (identifier) @label)

(jmp_statement
  label: (identifier) @label)

(il_label
  name: (identifier) @label)

; ---------------------------------------------------------------------------
; Literals
; ---------------------------------------------------------------------------

(integer_literal) @number

(real_literal) @number.float

(boolean_literal) @boolean

[
  (time_literal)
  (date_literal)
  (time_of_day_literal)
  (date_and_time_literal)
] @string.special

(string_literal) @string

; %IX0.0, %QW2, %MD10: hardware addresses
(direct_variable) @constant.builtin

; ---------------------------------------------------------------------------
; Pragmas and comments
; ---------------------------------------------------------------------------

(pragma) @attribute

(pragma
  (conditional_pragma)) @keyword.directive

(comment) @comment @spell

; (** ... *) and /// ... are documentation comments by convention.
((comment) @comment.documentation
  (#match? @comment.documentation "^[(][*][*][^*)]"))

((comment) @comment.documentation
  (#match? @comment.documentation "^///[^/]"))
