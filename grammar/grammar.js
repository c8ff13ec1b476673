/**
 * @file Tree-sitter grammar for IEC 61131-3 (rung)
 *
 * Covers Structured Text, Instruction List, textual SFC and configurations,
 * with the dialects of CODESYS V2.3 and V3, TwinCAT 3, OpenPCS and
 * Beremiz/OpenPLC: object-oriented extensions, pragmas, both POU shapes
 * (with and without END_ keywords) and code fragments at top level.
 *
 * Keywords are case-insensitive and reserved only where they must be: the
 * external scanner turns METHOD, PROPERTY, ACTION, STEP, TRANSITION, GET,
 * SET, CLASS, NAMESPACE, INTERFACE, USING, TYPE and AT into keywords only
 * where a declaration may start and the next token looks like one.
 */

/* eslint-disable arrow-parens, camelcase, max-len */

// ---------------------------------------------------------------------------
// Operator precedence: the one table (highest number binds tightest).
//   ()  call  ^ . []  unary - + NOT  **  * / MOD  + -  < > <= >=  = <>
//   AND &  AND_THEN  XOR  OR  OR_ELSE
// ---------------------------------------------------------------------------
const PREC = {
  OR_ELSE: 1,
  OR: 2,
  XOR: 3,
  AND_THEN: 4,
  AND: 5,
  EQUALITY: 6,
  COMPARISON: 7,
  ADDITIVE: 8,
  MULTIPLICATIVE: 9,
  POWER: 10,
  UNARY: 11,
  POSTFIX: 12,
  CALL: 13,
};

// [operator, precedence]; word operators are case-insensitive keywords.
const BINARY_OPERATORS = [
  ['OR_ELSE', PREC.OR_ELSE],
  ['OR', PREC.OR],
  ['XOR', PREC.XOR],
  ['AND_THEN', PREC.AND_THEN],
  ['AND', PREC.AND],
  ['&', PREC.AND],
  ['=', PREC.EQUALITY],
  ['<>', PREC.EQUALITY],
  ['<', PREC.COMPARISON],
  ['>', PREC.COMPARISON],
  ['<=', PREC.COMPARISON],
  ['>=', PREC.COMPARISON],
  ['+', PREC.ADDITIVE],
  ['-', PREC.ADDITIVE],
  ['*', PREC.MULTIPLICATIVE],
  ['/', PREC.MULTIPLICATIVE],
  ['MOD', PREC.MULTIPLICATIVE],
  ['**', PREC.POWER],
];

const VAR_KEYWORDS = [
  'VAR', 'VAR_INPUT', 'VAR_OUTPUT', 'VAR_IN_OUT', 'VAR_GLOBAL', 'VAR_EXTERNAL',
  'VAR_TEMP', 'VAR_STAT', 'VAR_INST', 'VAR_CONFIG', 'VAR_ACCESS',
];

const VAR_QUALIFIERS = ['CONSTANT', 'RETAIN', 'PERSISTENT', 'NON_RETAIN'];

const MODIFIERS = ['PUBLIC', 'PRIVATE', 'PROTECTED', 'INTERNAL', 'ABSTRACT', 'FINAL'];

/**
 * A case-insensitive keyword shown as its upper-case spelling.
 * @param {string} word
 * @return {AliasRule}
 */
function kw(word) {
  return alias(new RegExp(word.replace(/[^A-Za-z0-9_]/g, '\\$&'), 'i'), word);
}

/**
 * A case-insensitive spelling shown as another keyword.
 * @param {string} spelling
 * @param {string} shown
 * @return {AliasRule}
 */
function kwAs(spelling, shown) {
  return alias(new RegExp(spelling, 'i'), shown);
}

/**
 * One or more rules separated by commas.
 * @param {Rule} rule
 * @return {SeqRule}
 */
function commaSep1(rule) {
  return seq(rule, repeat(seq(',', rule)));
}

/**
 * Zero or more rules separated by commas.
 * @param {Rule} rule
 * @return {ChoiceRule}
 */
function commaSep(rule) {
  return optional(commaSep1(rule));
}

/**
 * Variable blocks and members, then an optional body and more members (the
 * TwinCAT/CODESYS object shape: each member ends where the next one starts).
 * @param {GrammarSymbols} $
 * @return {Rule[]}
 */
function pouContents($) {
  return [
    // OpenPCS declares POU-local types among the variable blocks
    repeat(choice($.var_block, $.type_declaration, $._member)),
    optional(seq(field('body', $._body), repeat($._member))),
  ];
}

/**
 * The parts of a variable declaration before its closing ';'.
 * @param {GrammarSymbols} $
 * @return {Rule[]}
 */
function varDeclarationCore($) {
  return [
    optional(commaSep1(field('name', choice($.identifier, alias($._dotted_name, $.qualified_name))))),
    optional(field('location', $.location)),
    ':',
    field('type', choice($._type_spec, alias($._inline_struct, $.struct_type), $.variadic_type,
      alias($._implicit_enum, $.enum_type))),
    optional(field('edge', choice(kw('R_EDGE'), kw('F_EDGE')))),
    optional(field('arguments', choice($.argument_list, $.argument_lists))),
    optional(seq(
      choice(':=', kwAs('REF=', 'REF=')),
      field('value', $._initializer),
    )),
  ];
}

/**
 * Declarations of a VAR block, STRUCT or UNION: each ends with ';' except
 * perhaps the last.
 * @param {GrammarSymbols} $
 * @return {Rule[]}
 */
function declarationList($) {
  return [
    repeat(choice($.var_declaration, $.empty_declaration)),
    optional(alias($._last_var_declaration, $.var_declaration)),
  ];
}

/**
 * An OpenPCS SFC step macro without its end: @ACTIVATE_STEP(S), @DEACTIVATE_STEP(S),
 * @DEACTIVATE_ALL_STEPS().
 * @param {GrammarSymbols} $
 * @return {Rule[]}
 */
function stepMacro($) {
  return [
    '@',
    field('name', choice(kw('ACTIVATE_STEP'), kw('DEACTIVATE_STEP'), kw('DEACTIVATE_ALL_STEPS'))),
    '(',
    optional(field('step', $.identifier)),
    ')',
  ];
}

module.exports = grammar({
  name: 'iec61131',

  word: $ => $.identifier,

  externals: $ => [
    $.comment,
    $.attribute_pragma,
    $.conditional_pragma,
    $.message_pragma,
    $.region_pragma,
    $.generic_pragma,
    $._il_newline,
    $._kw_method,
    $._kw_property,
    $._kw_action,
    $._kw_step,
    $._kw_transition,
    $._kw_get,
    $._kw_set,
    $._kw_class,
    $._kw_namespace,
    $._kw_interface,
    $._kw_using,
    $._kw_type,
    $._kw_at,
    $._kw_configuration,
    $._kw_resource,
    $._kw_initial_step,
    $._kw_jmp,
    $._kw_opc,
    $._il_same_line,
    $._argument_semicolon,
    $._error_sentinel,
  ],

  extras: $ => [/[\s\uFEFF\u00A0]/, $.comment, $.pragma],

  // Hidden rules the parser need not reduce: each would otherwise cost one reduction (a stack
  // pop, a heap-allocated one-child node, a push) per literal or operand; on the generated 1M-line
  // project _primary_expression alone is 90 MB of tree and 13% of the parse time. The other
  // wrappers (_expression, _reference, _statement, _assignment_operator) would save more, but
  // tree-sitter only inserts a MISSING token where a reduction follows it, so without them
  // `x := ;` and `x + 1;` lose their "missing expression" / "missing ':='" repairs
  // (tests/parser/syntax_errors and document_test catch this).
  inline: $ => [$._literal, $._primary_expression],

  conflicts: $ => [
    [$._top_level_statements],
    [$.var_declaration, $.label, $.il_label],
    [$._dotted_name, $._reference],
    [$.case_element],
    [$._reference, $._il_operator],
    [$.return_statement, $._il_operator],
    [$._bare_call, $._fragment_expression],
    [$._bare_call, $._reference],
    [$.label, $.il_label],
    [$._type_spec, $.subrange_type],
    [$.label, $._reference],
    [$.call_statement, $._reference],
    [$._top_level_item, $._closed_item_and_fragments],
    [$._reference, $.qualified_name],
  ],

  rules: {
    // -----------------------------------------------------------------------
    // Top level
    // -----------------------------------------------------------------------
    // Bare expression lines (manual examples listing literals or addresses
    // one per line) may start the file or follow an item that is closed by
    // its own last token (END_VAR, END_TYPE, ';' of a declaration line, ...);
    // never a POU, a statement list or IL, which may end without a closing
    // keyword: error recovery in a POU body must not find a cheap way out.
    source_file: $ => seq(
      repeat($.expression_fragment),
      repeat(choice(
        $._top_level_item,
        $._closed_item_and_fragments,
      )),
    ),

    _closed_item_and_fragments: $ => prec.right(seq(
      $._closed_top_level_item,
      repeat1($.expression_fragment),
    )),

    _top_level_item: $ => choice(
      $._pou_item,
      $._closed_top_level_item,
      alias($._top_level_statements, $.statement_list),
      $.il_body,
      $.sfc_network,
    ),

    _closed_top_level_item: $ => choice(
      $.configuration_declaration,
      $.resource_declaration,
      $.using_directive,
      $.type_declaration,
      $.var_block,
      // declaration lines without their VAR block (fragments)
      prec.dynamic(-2, $.var_declaration),
    ),

    // An expression alone on its line, perhaps closed by ';'. Only directly
    // in source_file, never in a POU body (where a bare expression stays a
    // syntax error). The end of the line is the IL one (the external scanner
    // tells it), so that the fragment never runs into the next line.
    expression_fragment: $ => prec.dynamic(-10, choice(
      seq(field('value', $._expression), $._il_newline),
      // "f();" is a call statement, never a fragment
      seq(field('value', $._fragment_expression), ';'),
    )),

    _fragment_expression: $ => choice(
      $.binary_expression,
      $.unary_expression,
      $.identifier,
      $.direct_variable,
      $.member_expression,
      $.index_expression,
      $.dereference_expression,
      $.parenthesized_expression,
      alias($._parenthesized_member, $.member_expression),
      alias($._parenthesized_dereference, $.dereference_expression),
      $.struct_initializer,
      $.array_initializer,
      $._literal,
    ),

    _declaration_item: $ => choice(
      $._pou_item,
      $.using_directive,
      $.type_declaration,
      $.var_block,
    ),

    _pou_item: $ => choice(
      $.program_declaration,
      $.function_declaration,
      $.function_block_declaration,
      $.method_declaration,
      $.property_declaration,
      $.interface_declaration,
      $.action_declaration,
      $.transition_declaration,
      $.class_declaration,
      $.namespace_declaration,
    ),

    // {attribute 'x' := 'y'}, {IF defined(x)}, {warning '...'}, {region "x"}, ...
    // The external scanner reads the text between the braces and tells its kind.
    pragma: $ => seq(
      '{',
      choice(
        $.attribute_pragma,
        $.conditional_pragma,
        $.message_pragma,
        $.region_pragma,
        $.generic_pragma,
      ),
      '}',
    ),

    qualified_name: $ => seq($.identifier, repeat(seq('.', $.identifier))),

    _dotted_name: $ => seq($.identifier, repeat1(seq('.', $.identifier))),

    // Greedy: a body that starts with the global scope operator (.x := 1) right after a result
    // type (METHOD M : T) is rare, a dotted type name (Lib.T) is not.
    type_name: $ => prec.right(seq($.identifier, optional($._type_name_tail))),

    _type_name_tail: $ => prec.right(seq('.', $.identifier, optional($._type_name_tail))),

    // -----------------------------------------------------------------------
    // POUs
    // -----------------------------------------------------------------------
    program_declaration: $ => prec.right(seq(
      kw('PROGRAM'),
      // TwinCAT: PROGRAM INTERNAL P (access modifier before the name, as for FUNCTION_BLOCK)
      repeat($.modifier),
      field('name', $.identifier),
      ...pouContents($),
      optional(kw('END_PROGRAM')),
    )),

    function_declaration: $ => prec.right(seq(
      kw('FUNCTION'),
      repeat($.modifier),
      field('name', $.identifier),
      optional(field('type_parameters', $.generic_parameters)),
      optional(seq(':', field('type', $._type_spec))),
      repeat(choice($.var_block, $.type_declaration)),
      optional(field('body', $._body)),
      optional(kw('END_FUNCTION')),
    )),

    function_block_declaration: $ => prec.right(seq(
      choice(kw('FUNCTION_BLOCK'), kwAs('FUNCTIONBLOCK', 'FUNCTION_BLOCK')),
      $._class_header,
      ...pouContents($),
      optional(choice(kw('END_FUNCTION_BLOCK'), kwAs('END_FUNCTIONBLOCK', 'END_FUNCTION_BLOCK'))),
    )),

    class_declaration: $ => prec.right(seq(
      alias($._kw_class, 'CLASS'),
      $._class_header,
      ...pouContents($),
      optional(kw('END_CLASS')),
    )),

    _class_header: $ => seq(
      repeat($.modifier),
      field('name', $.identifier),
      repeat($.modifier),
      // TwinCAT 3.1.4026 / CODESYS generic constants come before EXTENDS and IMPLEMENTS.
      optional($.generic_constant_block),
      optional($.extends_clause),
      optional($.implements_clause),
    ),

    // VAR_GENERIC CONSTANT MaxCount : UDINT := 10; END_VAR
    generic_constant_block: $ => seq(
      kw('VAR_GENERIC'),
      optional(alias(kw('CONSTANT'), $.var_qualifier)),
      repeat(choice($.var_declaration, $.empty_declaration)),
      kw('END_VAR'),
    ),

    // FB_Buffer<100>, FB_Buffer<(2 * cSize)>, FB_Buffer<N>: an instance of a generic FB.
    generic_type: $ => seq(
      field('type', $.type_name),
      token.immediate('<'),
      commaSep1(field('argument', choice($.integer_literal, $.identifier, alias($._dotted_name, $.qualified_name),
        $.parenthesized_expression))),
      '>',
    ),

    // Variable blocks and members, then an optional body and more members
    // (TwinCAT/CODESYS object shape: each member ends where the next starts).

    _member: $ => choice(
      $.method_declaration,
      $.property_declaration,
      $.action_declaration,
      $.transition_declaration,
    ),

    modifier: _ => choice(...MODIFIERS.map(kw)),

    extends_clause: $ => seq(kw('EXTENDS'), commaSep1(choice($.type_name, $.generic_type))),

    implements_clause: $ => seq(kw('IMPLEMENTS'), commaSep1($.type_name)),

    generic_parameters: $ => seq('<', commaSep1($.generic_parameter), '>'),

    generic_parameter: $ => seq(
      field('name', $.identifier),
      ':',
      field('constraint', $.type_name),
    ),

    method_declaration: $ => prec.right(seq(
      alias($._kw_method, 'METHOD'),
      repeat($.modifier),
      field('name', $.identifier),
      repeat($.modifier),
      optional(seq(':', field('type', $._type_spec), repeat($.modifier))),
      // TwinCAT code may end the header with ';' (METHOD PUBLIC M : BOOL;). It belongs to the
      // header when variable blocks follow; otherwise it is the body's empty statement.
      choice(prec(1, seq(';', repeat1($.var_block))), repeat($.var_block)),
      optional(field('body', $._body)),
      optional(kw('END_METHOD')),
    )),

    property_declaration: $ => prec.right(choice(
      seq(
        alias($._kw_property, 'PROPERTY'),
        repeat($.modifier),
        field('name', $.identifier),
        repeat($.modifier),
        optional(seq(':', field('type', $._type_spec), repeat($.modifier))),
        // Old TwinCAT libraries end the header with ';' ("PROPERTY P : STRING;").
        optional(';'),
        repeat($.var_block),
        repeat($.property_accessor),
        optional(kw('END_PROPERTY')),
      ),
      // IEC 61131-3 (2025) form
      seq(
        field('accessor', choice(kw('PROPERTY_GET'), kw('PROPERTY_SET'))),
        repeat($.modifier),
        field('name', $.identifier),
        repeat($.modifier),
        optional(seq(':', field('type', $._type_spec), repeat($.modifier))),
        repeat($.var_block),
        optional(field('body', $._body)),
        optional(kw('END_PROPERTY')),
      ),
    )),

    property_accessor: $ => prec.right(seq(
      field('kind', choice(alias($._kw_get, 'GET'), alias($._kw_set, 'SET'))),
      repeat($.modifier),
      repeat($.var_block),
      optional(field('body', $._body)),
      optional(choice(kw('END_GET'), kw('END_SET'))),
    )),

    interface_declaration: $ => prec.right(seq(
      alias($._kw_interface, 'INTERFACE'),
      repeat($.modifier),
      field('name', $.identifier),
      optional($.extends_clause),
      repeat(choice($.method_declaration, $.property_declaration, $.var_block)),
      optional(kw('END_INTERFACE')),
    )),

    action_declaration: $ => prec.right(seq(
      alias($._kw_action, 'ACTION'),
      field('name', $.identifier),
      optional(':'),
      repeat($.var_block),
      optional(field('body', $._body)),
      optional(kw('END_ACTION')),
    )),

    // A transition object of a TwinCAT/CODESYS SFC ("TRANSITION T:"): its body
    // is either one boolean expression or a statement list.
    transition_declaration: $ => prec.right(seq(
      alias($._kw_transition, 'TRANSITION'),
      field('name', $.identifier),
      ':',
      optional(choice(
        prec.dynamic(1, seq(field('body', $._expression), optional(';'))),
        field('body', $.statement_list),
      )),
      optional(seq(kw('END_TRANSITION'), optional(';'))),
    )),

    namespace_declaration: $ => seq(
      alias($._kw_namespace, 'NAMESPACE'),
      field('name', $.qualified_name),
      repeat($._declaration_item),
      kw('END_NAMESPACE'),
    ),

    using_directive: $ => seq(
      alias($._kw_using, 'USING'),
      commaSep1($.qualified_name),
      ';',
    ),

    _body: $ => choice($.statement_list, $.il_body, alias($._sfc_body_network, $.sfc_network)),

    // -----------------------------------------------------------------------
    // Data types
    // -----------------------------------------------------------------------
    type_declaration: $ => prec.right(seq(
      alias($._kw_type, 'TYPE'),
      repeat(choice($.struct_type, $.union_type, $.enum_type, $.alias_type)),
      kw('END_TYPE'),
      optional(';'),
    )),

    // The ':' is required; without it (TYPE S STRUCT ..., as old manuals print it) the struct
    // still parses so that its members are read, and the syntax checks report the missing ':'.
    // TwinCAT puts access and inheritance modifiers before the name: TYPE INTERNAL E : (...),
    // TYPE ABSTRACT S : STRUCT ...
    struct_type: $ => prec.right(seq(
      repeat($.modifier),
      field('name', $.identifier),
      optional($.extends_clause),
      optional(':'),
      kw('STRUCT'),
      optional($.extends_clause),
      ...declarationList($),
      kw('END_STRUCT'),
      optional(seq(':=', field('value', $._initializer))),
      optional(';'),
    )),

    // STRUCT ... END_STRUCT written inside a variable declaration
    _inline_struct: $ => seq(
      kw('STRUCT'),
      ...declarationList($),
      kw('END_STRUCT'),
    ),

    union_type: $ => seq(
      repeat($.modifier),
      field('name', $.identifier),
      ':',
      kw('UNION'),
      ...declarationList($),
      kw('END_UNION'),
      optional(';'),
    ),

    enum_type: $ => prec.right(seq(
      repeat($.modifier),
      field('name', $.identifier),
      ':',
      optional(field('base', $.type_name)),
      '(',
      commaSep1($.enum_value),
      optional(','),
      ')',
      optional(field('base', $.type_name)),
      optional(seq(':=', field('value', $._expression))),
      optional(';'),
    )),

    enum_value: $ => seq(
      field('name', $.identifier),
      optional(seq(':=', field('value', $._expression))),
    ),

    alias_type: $ => seq(
      repeat($.modifier),
      field('name', $.identifier),
      ':',
      field('type', $._type_spec),
      optional(seq(':=', field('value', $._initializer))),
      optional(';'),
    ),

    _type_spec: $ => choice(
      $.type_name,
      $.generic_type,
      $.string_type,
      $.array_type,
      $.pointer_type,
      $.reference_type,
      $.subrange_type,
    ),

    string_type: $ => prec.right(seq(
      choice(kw('STRING'), kw('WSTRING')),
      optional(choice(
        seq('(', field('length', $._expression), ')'),
        seq('[', field('length', $._expression), ']'),
      )),
    )),

    array_type: $ => seq(
      kw('ARRAY'),
      '[',
      commaSep1(choice($.range, alias('*', $.wildcard))),
      ']',
      kw('OF'),
      field('element', $._type_spec),
    ),

    range: $ => seq(
      field('lower', $._expression),
      '..',
      field('upper', $._expression),
    ),

    pointer_type: $ => prec.right(seq(kw('POINTER'), optional(seq(kw('TO'), field('type', $._type_spec))))),

    reference_type: $ => seq(
      choice(seq(kw('REFERENCE'), kw('TO')), kw('REF_TO')),
      field('type', $._type_spec),
    ),

    subrange_type: $ => seq(
      field('base', $.type_name),
      '(',
      field('range', $.range),
      ')',
    ),

    // -----------------------------------------------------------------------
    // Variable declarations
    // -----------------------------------------------------------------------
    var_block: $ => prec.right(choice(
      seq(
        field('kind', choice(...VAR_KEYWORDS.filter(k => k !== 'VAR_ACCESS').map(kw))),
        repeat($.var_qualifier),
        ...declarationList($),
        kw('END_VAR'),
        optional(';'),
      ),
      // access paths of a configuration or resource
      seq(
        field('kind', kw('VAR_ACCESS')),
        repeat($.var_qualifier),
        repeat(choice($.access_declaration, $.var_declaration, $.empty_declaration)),
        optional(alias($._last_var_declaration, $.var_declaration)),
        kw('END_VAR'),
        optional(';'),
      ),
    )),

    empty_declaration: _ => ';',

    // OPC (OpenPCS: publish to the OPC server) is a contextual word: a variable may be named OPC.
    var_qualifier: $ => choice(...VAR_QUALIFIERS.map(kw), alias($._kw_opc, 'OPC')),

    // A declaration ends with ';'; only the last one of a block (right before
    // END_VAR / END_STRUCT / END_UNION) may leave it out.
    var_declaration: $ => seq(...varDeclarationCore($), ';'),

    _last_var_declaration: $ => prec.right(seq(...varDeclarationCore($))),

    // VAR_ACCESS: ABLE : Station_1.%IX1.1 : BOOL READ_ONLY;
    access_declaration: $ => seq(
      field('name', $.identifier),
      ':',
      field('path', $.access_path),
      ':',
      field('type', $._type_spec),
      optional(field('direction', choice(kw('READ_ONLY'), kw('READ_WRITE')))),
      ';',
    ),

    access_path: $ => choice($.direct_variable, $._access_path_segments),

    _access_path_segments: $ => seq(
      $.identifier,
      optional(seq('.', choice($.direct_variable, $._access_path_segments))),
    ),

    // RuSTy variadic inputs: IN : {sized} T...;  args : ...;
    // The '...' follows its type directly, so that an elision line after a declaration
    // ("x : INT;" NEWLINE "...") is no variadic type.
    variadic_type: $ => choice(seq(field('type', $._type_spec), token.immediate('...')), '...'),

    // FB_init arguments of each element of an array of function blocks:
    // aFb : ARRAY[0..1] OF FB_X[(a := 1), (a := 2)];
    argument_lists: $ => seq('[', commaSep1($.argument_list), ']'),

    location: $ => seq(alias($._kw_at, 'AT'), field('address', $.direct_variable)),

    _initializer: $ => choice(
      $._init_element,
      alias($._bare_array_initializer, $.array_initializer),
    ),

    _bare_array_initializer: $ => seq($._init_element, repeat1(seq(',', $._init_element))),

    _init_element: $ => choice($._expression, $.repeated_initializer),

    repeated_initializer: $ => seq(
      field('count', $.integer_literal),
      '(',
      optional(commaSep1($._init_element)),
      ')',
    ),

    array_initializer: $ => seq(
      '[',
      optional(seq(commaSep1($._init_element), optional(','))),
      ']',
    ),

    struct_initializer: $ => seq(
      '(',
      commaSep1($.field_initializer),
      optional(','),
      ')',
    ),

    field_initializer: $ => seq(
      field('name', $.identifier),
      ':=',
      field('value', $._init_element),
    ),

    // -----------------------------------------------------------------------
    // Structured Text statements
    // -----------------------------------------------------------------------
    statement_list: $ => prec.right(repeat1($._statement)),

    // Statements at top level: GLR decides where a declaration line starts.
    _top_level_statements: $ => prec.dynamic(-1, repeat1($._statement)),

    _statement: $ => choice(
      $.assignment_statement,
      $.call_statement,
      $.if_statement,
      $.case_statement,
      $.for_statement,
      $.while_statement,
      $.repeat_statement,
      $.exit_statement,
      $.continue_statement,
      $.return_statement,
      $.jmp_statement,
      $.label,
      $.empty_statement,
      $.try_statement,
      alias($._st_step_macro, $.sfc_step_macro),
    ),

    _assignment_operator: _ => choice(
      ':=',
      kwAs('S=', 'S='),
      kwAs('R=', 'R='),
      kwAs('REF=', 'REF='),
      '?=',
    ),

    assignment_statement: $ => seq(
      field('left', $._reference),
      field('operator', $._assignment_operator),
      field('right', choice($._expression, $.assignment_expression)),
      ';',
    ),

    // CODESYS multiple assignment: a := b := 0; and ExST a S= b R= F(x); (every target takes
    // the value at the end of the line).
    assignment_expression: $ => prec.right(seq(
      field('left', $._reference),
      field('operator', choice(':=', kwAs('S=', 'S='), kwAs('R=', 'R='))),
      field('right', choice($._expression, $.assignment_expression)),
    )),

    call_statement: $ => choice(
      seq($.call_expression, ';'),
      // CODESYS 2.3 calls a program without parentheses: "Read_Inputs;".
      prec.dynamic(-1, seq(alias($._bare_call, $.call_expression), ';')),
    ),

    _bare_call: $ => field('function', choice($.identifier, $.member_expression)),

    if_statement: $ => prec.right(seq(
      kw('IF'),
      field('condition', $._expression),
      kw('THEN'),
      optional(field('body', $.statement_list)),
      repeat($.elsif_clause),
      optional($.else_clause),
      kw('END_IF'),
      optional(';'),
    )),

    elsif_clause: $ => seq(
      kw('ELSIF'),
      field('condition', $._expression),
      kw('THEN'),
      optional(field('body', $.statement_list)),
    ),

    else_clause: $ => seq(kw('ELSE'), optional(field('body', $.statement_list))),

    case_statement: $ => prec.right(seq(
      kw('CASE'),
      field('value', $._expression),
      kw('OF'),
      repeat($.case_element),
      optional($.else_clause),
      kw('END_CASE'),
      optional(';'),
    )),

    case_element: $ => seq(
      commaSep1(field('label', choice($._expression, $.range))),
      ':',
      optional(field('body', alias($._case_body, $.statement_list))),
    ),

    // Statements of a case element; GLR decides where the next label starts.
    _case_body: $ => repeat1($._statement),

    for_statement: $ => prec.right(seq(
      kw('FOR'),
      field('variable', $._reference),
      ':=',
      field('start', $._expression),
      kw('TO'),
      field('end', $._expression),
      optional(seq(kw('BY'), field('step', $._expression))),
      kw('DO'),
      optional(field('body', $.statement_list)),
      kw('END_FOR'),
      optional(';'),
    )),

    while_statement: $ => prec.right(seq(
      kw('WHILE'),
      field('condition', $._expression),
      kw('DO'),
      optional(field('body', $.statement_list)),
      kw('END_WHILE'),
      optional(';'),
    )),

    repeat_statement: $ => prec.right(seq(
      kw('REPEAT'),
      optional(field('body', $.statement_list)),
      kw('UNTIL'),
      field('condition', $._expression),
      optional(';'),
      kw('END_REPEAT'),
      optional(';'),
    )),

    exit_statement: _ => seq(kw('EXIT'), ';'),

    continue_statement: _ => seq(kw('CONTINUE'), ';'),

    // CODESYS/TwinCAT conditional return: RETURN (bDone); leaves the POU when bDone is TRUE.
    return_statement: $ => seq(kw('RETURN'), optional(field('condition', $._expression)), ';'),

    jmp_statement: $ => seq(alias($._kw_jmp, 'JMP'), field('label', $.identifier), ';'),

    label: $ => prec.dynamic(-1, seq(field('name', $.identifier), ':')),

    empty_statement: _ => ';',

    // TwinCAT exception handling
    try_statement: $ => prec.right(seq(
      kw('__TRY'),
      optional(field('body', $.statement_list)),
      optional($.catch_clause),
      optional($.finally_clause),
      kw('__ENDTRY'),
      optional(';'),
    )),

    catch_clause: $ => seq(
      kw('__CATCH'),
      optional(seq('(', field('exception', $.identifier), ')')),
      optional(field('body', $.statement_list)),
    ),

    finally_clause: $ => seq(kw('__FINALLY'), optional(field('body', $.statement_list))),

    // -----------------------------------------------------------------------
    // Expressions
    // -----------------------------------------------------------------------
    _expression: $ => choice(
      $.binary_expression,
      $.unary_expression,
      $._primary_expression,
    ),

    binary_expression: $ => choice(...BINARY_OPERATORS.map(([op, p]) => prec.left(p, seq(
      field('left', $._expression),
      field('operator', /^[A-Z_]+$/.test(op) ? kw(op) : op),
      field('right', $._expression),
    )))),

    unary_expression: $ => prec(PREC.UNARY, seq(
      field('operator', choice('-', '+', kw('NOT'), '&')),
      field('operand', $._expression),
    )),

    _primary_expression: $ => choice(
      $._reference,
      $.parenthesized_expression,
      alias($._parenthesized_member, $.member_expression),
      alias($._parenthesized_dereference, $.dereference_expression),
      $.struct_initializer,
      $.array_initializer,
      $._literal,
    ),

    // Anything that may be assigned, called or followed by . [ ] ^
    _reference: $ => choice(
      $.identifier,
      $.global_reference,
      $.direct_variable,
      $.member_expression,
      $.index_expression,
      $.dereference_expression,
      $.call_expression,
    ),

    _postfix_target: $ => prec(1, $._reference),

    // CODESYS V3 global scope operator: .ivar is the global ivar even where a local one hides it.
    global_reference: $ => seq('.', field('name', $.identifier)),

    parenthesized_expression: $ => seq('(', $._expression, ')'),

    // CODESYS implicit enumeration in a declaration: eState : (IDLE, BUSY, ERROR) := IDLE;
    _implicit_enum: $ => seq(
      '(',
      commaSep1($.enum_value),
      ')',
      optional(field('base', $.type_name)),
    ),

    // Dereference of a computed pointer, (pData + i * SIZEOF(INT))^: a value only.
    _parenthesized_dereference: $ => prec(PREC.POSTFIX, seq(
      field('operand', $.parenthesized_expression),
      '^',
    )),

    // Bit or member of a parenthesized value, (a OR b).0: a value only, never
    // assigned (a statement never starts with "(").
    _parenthesized_member: $ => prec(PREC.POSTFIX, seq(
      field('object', choice($.parenthesized_expression, alias($._parenthesized_dereference, $.dereference_expression))),
      '.',
      field('member', choice($.identifier, $.integer_literal)),
    )),

    member_expression: $ => prec(PREC.POSTFIX, seq(
      field('object', $._postfix_target),
      '.',
      field('member', choice($.identifier, $.integer_literal, $.direct_variable)),
    )),

    index_expression: $ => prec(PREC.POSTFIX, seq(
      field('object', $._postfix_target),
      '[',
      commaSep1(field('index', $._expression)),
      ']',
    )),

    dereference_expression: $ => prec(PREC.POSTFIX, seq(
      field('operand', $._postfix_target),
      '^',
    )),

    call_expression: $ => prec(PREC.CALL, seq(
      field('function', $._reference),
      field('arguments', $.argument_list),
    )),

    argument_list: $ => seq(
      '(',
      optional(seq(
        choice($.argument, $.output_argument),
        repeat(seq(choice(',', '|', $._wrong_argument_separator), choice($.argument, $.output_argument))),
        // The input assistant of TwinCAT/CODESYS leaves "ErrorID => ," before the ')'.
        optional(','),
      )),
      ')',
    ),

    // SHL(in_word;n): a ';' between arguments that the same line closes with ')' (the scanner
    // tells). It can never be completed (the sentinel only exists in error recovery), so the
    // ';' is reported where it stands, and the arguments after it still belong to the call.
    _wrong_argument_separator: $ => seq(alias($._argument_semicolon, ';'), $._unreachable),

    argument: $ => choice(
      seq(field('name', $.identifier), ':=', optional(field('value', choice($._expression, $.il_expression)))),
      field('value', $._expression),
    ),

    output_argument: $ => seq(
      optional(field('negation', kw('NOT'))),
      field('name', $.identifier),
      '=>',
      optional(field('target', $._reference)),
    ),

    // -----------------------------------------------------------------------
    // Literals
    // -----------------------------------------------------------------------
    _literal: $ => choice(
      $.integer_literal,
      $.real_literal,
      $.boolean_literal,
      $.time_literal,
      $.date_literal,
      $.time_of_day_literal,
      $.date_and_time_literal,
      $.string_literal,
      $.typed_literal,
    ),

    integer_literal: _ => token(choice(
      /[0-9][0-9_]*/,
      /2#[01_]+/,
      /8#[0-7_]+/,
      /16#[0-9A-Fa-f_]+/,
      /10#[0-9_]+/,  // explicit decimal, accepted by CODESYS and TwinCAT (TcUnit examples)
    )),

    real_literal: _ => token(choice(
      /[0-9][0-9_]*\.[0-9][0-9_]*([eE][+-]?[0-9][0-9_]*)?/,
      /[0-9][0-9_]*[eE][+-]?[0-9][0-9_]*/,
    )),

    boolean_literal: _ => choice(kw('TRUE'), kw('FALSE')),

    // Unit order is not checked here (a later, semantic check does it).
    time_literal: _ => token(/(t|time|lt|ltime)#[ \t]*[+-]?([0-9][0-9_]*(\.[0-9]+)?(d|h|m|s|ms|us|ns)_?)+/i),

    date_literal: _ => token(/(d|date|ld|ldate)#[ \t]*[0-9]+-[0-9]+-[0-9]+/i),

    time_of_day_literal: _ => token(/(tod|time_of_day|ltod|ltime_of_day)#[ \t]*[0-9]+:[0-9]+(:[0-9]+(\.[0-9]+)?)?/i),

    date_and_time_literal: _ => token(/(dt|date_and_time|ldt|ldate_and_time)#[ \t]*[0-9]+-[0-9]+-[0-9]+-[0-9]+:[0-9]+(:[0-9]+(\.[0-9]+)?)?/i),

    string_literal: _ => token(choice(
      /'([^'$\r\n]|\$[^\r\n])*'/,
      /"([^"$\r\n]|\$[^\r\n])*"/,
    )),

    // INT#5, UINT#16#FF, BOOL#TRUE, REAL#1.5, STRING#'x', E_Color#Red
    typed_literal: $ => seq(
      field('type', $.identifier),
      token.immediate('#'),
      field('value', choice(
        seq(optional(choice('-', '+')), choice($.integer_literal, $.real_literal)),
        $.boolean_literal,
        $.string_literal,
        $.identifier,
      )),
    ),

    direct_variable: _ => token(choice(
      /%[IQM][XBWDL]?(\*|[0-9]+(\.[0-9]+)*)/i,
      /%[XBWD][0-9]+/i,
    )),

    // -----------------------------------------------------------------------
    // Instruction List
    // -----------------------------------------------------------------------
    il_body: $ => prec.right(repeat1(choice($.il_instruction, $.il_label, $.sfc_step_macro, $._stray_closer))),

    // OpenPCS step control in the IL code of an SFC: @ACTIVATE_STEP(S), @DEACTIVATE_STEP(S) and
    // @DEACTIVATE_ALL_STEPS() change which steps are active from the next cycle on. IL only.
    sfc_step_macro: $ => seq(...stepMacro($), $._il_newline),

    // The same macro written as an ST statement: not allowed there (the checker says so), but
    // read as one statement so that the POU around it stays whole.
    _st_step_macro: $ => seq(...stepMacro($), ';'),

    // A closing word of a declaration block where an instruction may start (a doubled END_VAR)
    // is lexed as that keyword and can never be completed (the scanner never produces the
    // sentinel outside error recovery): it becomes an ERROR node instead of an IL instruction
    // with an unknown operator.
    _stray_closer: $ => seq(choice(kw('END_VAR'), kw('END_STRUCT'), kw('END_TYPE')), $._unreachable),

    // The sentinel that never comes, visible so that the syntax checks find it when it is MISSING.
    _unreachable: $ => alias($._error_sentinel, 'unreachable'),

    il_label: $ => seq(field('name', choice($.identifier, alias(kw('CONTINUE'), $.identifier))), ':'),

    _il_operator: $ => choice(
      alias($.identifier, $.il_operator),
      ...['AND', 'OR', 'XOR', 'NOT', 'MOD', 'RETURN'].map(w => alias(new RegExp(w, 'i'), $.il_operator)),
      alias($._kw_jmp, $.il_operator),
    ),

    il_instruction: $ => choice(
      // IL is line-oriented: the operands stand on the operator's line (the external scanner
      // tells so), so "Foo" NEWLINE "Bar();" is never an instruction with an operand.
      seq(
        field('operator', $._il_operator),
        optional(seq($._il_same_line, commaSep1(field('operand', $._expression)))),
        $._il_newline,
      ),
      // deferred operator: AND( ... ) over several lines; the first line may hold an operand
      // (IEC: AND( %IX0.1) or, as CODESYS prints it, the load that opens the parentheses
      // (AND(LD %IX0.1)
      seq(
        field('operator', $._il_operator),
        '(',
        optional(choice(field('operand', $._expression), alias($._il_load_after_parenthesis, $.il_instruction))),
        $._il_newline,
        repeat(choice($.il_instruction, $.il_label)),
        ')',
        $._il_newline,
      ),
      // deferred operator on one line: MUL (2 ADD 3)
      seq(
        field('operator', $._il_operator),
        '(',
        field('operand', $._expression),
        repeat1(alias($._il_inline_instruction, $.il_instruction)),
        ')',
        $._il_newline,
      ),
    ),

    // An IL computation as the value of a CAL parameter (OpenPCS S5034): P := (a ADD b).
    il_expression: $ => seq(
      '(',
      field('operand', $._expression),
      repeat1(alias($._il_inline_instruction, $.il_instruction)),
      ')',
    ),

    // LD is a keyword only here (where an operand could also start), so "AND(LD x" is a load.
    _il_load_after_parenthesis: $ => seq(
      field('operator', choice(alias(/LD/i, $.il_operator), alias(/LDN/i, $.il_operator))),
      field('operand', $._expression),
    ),

    _il_inline_instruction: $ => seq(
      field('operator', $._il_operator),
      field('operand', $._expression),
    ),

    // -----------------------------------------------------------------------
    // Sequential Function Chart (textual)
    // -----------------------------------------------------------------------
    sfc_network: $ => prec.right(repeat1(choice($.sfc_step, $.sfc_transition))),

    // As the body of a POU or action a network starts with a step, so that a TwinCAT
    // "TRANSITION T:" object after an action with an empty body is not read as the start of a
    // network inside that body. (Top-level fragments may list transitions alone.)
    _sfc_body_network: $ => prec.right(seq($.sfc_step, repeat(choice($.sfc_step, $.sfc_transition, $.sfc_action_block)))),

    // An IEC action block inside an SFC network: ACTION name: ... END_ACTION (END_ACTION required
    // here, so the network can go on with steps and transitions after it).
    sfc_action_block: $ => prec.right(seq(
      alias($._kw_action, 'ACTION'),
      field('name', $.identifier),
      optional(':'),
      optional(field('body', choice($.statement_list, $.il_body))),
      kw('END_ACTION'),
      optional(';'),
    )),

    sfc_step: $ => prec.right(seq(
      choice(alias($._kw_initial_step, 'INITIAL_STEP'), alias($._kw_step, 'STEP')),
      field('name', $.identifier),
      ':',
      repeat($.sfc_action),
      kw('END_STEP'),
      optional(';'),
    )),

    // Action association inside a step: A1(N); A2(L, T#10s);
    sfc_action: $ => seq(
      field('name', $.identifier),
      '(',
      optional(seq(
        field('qualifier', $.identifier),
        repeat(seq(',', field('argument', $._expression))),
      )),
      ')',
      ';',
    ),

    sfc_transition: $ => prec.right(seq(
      alias($._kw_transition, 'TRANSITION'),
      optional(field('name', $.identifier)),
      optional(seq('(', $.identifier, ':=', field('priority', $._expression), ')')),
      kw('FROM'),
      field('from', $._step_list),
      kw('TO'),
      field('to', $._step_list),
      choice(
        // IEC 61131-3 closes this form with END_TRANSITION too; CODESYS does not
        seq(':=', field('condition', $._expression), ';', optional(seq(kw('END_TRANSITION'), optional(';')))),
        seq(':', optional(field('body', choice($.statement_list, $.il_body))), kw('END_TRANSITION'), optional(';')),
      ),
    )),

    _step_list: $ => choice(
      $.identifier,
      seq('(', commaSep1($.identifier), ')'),
    ),

    // -----------------------------------------------------------------------
    // Configurations
    // -----------------------------------------------------------------------
    configuration_declaration: $ => seq(
      alias($._kw_configuration, 'CONFIGURATION'),
      field('name', $.identifier),
      repeat(choice($.var_block, $.resource_declaration, $.task_configuration, $.program_configuration)),
      kw('END_CONFIGURATION'),
    ),

    resource_declaration: $ => seq(
      alias($._kw_resource, 'RESOURCE'),
      field('name', $.identifier),
      optional(seq(kw('ON'), field('processor', $.type_name))),
      repeat(choice($.var_block, $.task_configuration, $.program_configuration)),
      kw('END_RESOURCE'),
    ),

    task_configuration: $ => seq(
      kw('TASK'),
      field('name', $.identifier),
      optional(field('arguments', $.argument_list)),
      ';',
    ),

    program_configuration: $ => seq(
      kw('PROGRAM'),
      optional(field('qualifier', $.var_qualifier)),
      field('name', $.identifier),
      optional(seq(kw('WITH'), field('task', $.identifier))),
      ':',
      field('type', $.type_name),
      optional(field('arguments', alias($._program_configuration_arguments, $.argument_list))),
      ';',
    ),

    // Arguments of a program configuration may also attach a function block
    // instance of the program to a task: (x := %IX1.1, FB1 WITH SLOW_1)
    _program_configuration_arguments: $ => seq(
      '(',
      commaSep(choice($.argument, $.output_argument, $.task_association)),
      ')',
    ),

    task_association: $ => seq(
      field('name', $.qualified_name),
      kw('WITH'),
      field('task', $.identifier),
    ),

    // Last, so that keywords (defined earlier) win over it when both match.
    identifier: _ => /[\p{L}_][\p{L}\p{Nd}_]*/,
  },
});
