/*
 * External scanner for the IEC 61131-3 grammar (rung).
 *
 * It produces the tokens that regular expressions cannot express:
 *  - comments: nested block comments "(* ... (* ... *) ... *)", C block
 *    comments and line comments;
 *  - pragmas "{...}", classified by their first word so that the tree tells
 *    attribute, conditional, message, region and other pragmas apart;
 *  - the end of an IL instruction line (only where the grammar expects one);
 *  - contextual keywords (METHOD, PROPERTY, ACTION, STEP, CONFIGURATION, ...): real code uses
 *    these words as variable names, so they are keywords only where the
 *    grammar allows them AND the next token looks like the start of a
 *    declaration rather than the rest of a statement ("Step := 1;").
 *
 * The scanner keeps no state.
 */

#include "tree_sitter/parser.h"

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

enum TokenType {
  COMMENT,
  ATTRIBUTE_PRAGMA,
  CONDITIONAL_PRAGMA,
  MESSAGE_PRAGMA,
  REGION_PRAGMA,
  GENERIC_PRAGMA,
  IL_NEWLINE,
  KW_METHOD,
  KW_PROPERTY,
  KW_ACTION,
  KW_STEP,
  KW_TRANSITION,
  KW_GET,
  KW_SET,
  KW_CLASS,
  KW_NAMESPACE,
  KW_INTERFACE,
  KW_USING,
  KW_TYPE,
  KW_AT,
  KW_CONFIGURATION,
  KW_RESOURCE,
  KW_INITIAL_STEP,
  KW_JMP,
  KW_OPC,
  IL_SAME_LINE,
  ARGUMENT_SEMICOLON,
  ERROR_SENTINEL,
  TOKEN_COUNT
};

/* Contextual keywords, in the order of their token types. */
static const char *const SOFT_KEYWORDS[] = {
    "METHOD", "PROPERTY",  "ACTION", "STEP", "TRANSITION", "GET", "SET",
    "CLASS",  "NAMESPACE", "INTERFACE", "USING", "TYPE", "AT",
    /* Not in TwinCAT's keyword list: "Configuration REF= x;" and "Resource := 1;" are statements. */
    "CONFIGURATION", "RESOURCE", "INITIAL_STEP",
    /* MATIEC accepts IL operator names as variables: "JMP := 1;" is an assignment. */
    "JMP",
    /* OpenPCS var-block qualifier (VAR CONSTANT OPC); elsewhere a name like any other. */
    "OPC",
};
#define SOFT_KEYWORD_COUNT (sizeof(SOFT_KEYWORDS) / sizeof(SOFT_KEYWORDS[0]))
/* read_soft_keyword keeps one bit per keyword. */
_Static_assert(SOFT_KEYWORD_COUNT <= 32, "too many contextual keywords for a 32-bit set");



void *tree_sitter_iec61131_external_scanner_create(void) { return NULL; }
void tree_sitter_iec61131_external_scanner_destroy(void *payload) { (void)payload; }
unsigned tree_sitter_iec61131_external_scanner_serialize(void *payload, char *buffer) {
  (void)payload;
  (void)buffer;
  return 0;
}
void tree_sitter_iec61131_external_scanner_deserialize(void *payload, const char *buffer,
                                                       unsigned length) {
  (void)payload;
  (void)buffer;
  (void)length;
}

static inline void advance(TSLexer *lexer) { lexer->advance(lexer, false); }
static inline void skip(TSLexer *lexer) { lexer->advance(lexer, true); }

static inline bool is_horizontal_space(int32_t c) {
  return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == 0xA0 || c == 0xFEFF;
}
static inline bool is_newline(int32_t c) { return c == '\n' || c == '\r'; }

static inline bool is_word_start(int32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c >= 0xC0;
}
static inline bool is_word_char(int32_t c) { return is_word_start(c) || (c >= '0' && c <= '9'); }

static inline int32_t to_upper(int32_t c) { return (c >= 'a' && c <= 'z') ? c - 32 : c; }

/* Skips a "(* ... *)" comment (nested), a C block comment or a line comment without producing a
 * token; the lookahead is on the opening character. Returns false when no comment starts here
 * (the opening character is consumed all the same). */
static bool skip_comment(TSLexer *lexer) {
  int32_t open = lexer->lookahead;
  advance(lexer);
  if (open == '(' && lexer->lookahead == '*') {
    advance(lexer);
    unsigned depth = 1;
    while (!lexer->eof(lexer) && depth > 0) {
      int32_t c = lexer->lookahead;
      advance(lexer);
      if (c == '*' && lexer->lookahead == ')') {
        advance(lexer);
        depth--;
      } else if (c == '(' && lexer->lookahead == '*') {
        advance(lexer);
        depth++;
      }
    }
    return true;
  }
  if (open == '/' && lexer->lookahead == '/') {
    while (!lexer->eof(lexer) && !is_newline(lexer->lookahead)) advance(lexer);
    return true;
  }
  if (open == '/' && lexer->lookahead == '*') {
    advance(lexer);
    while (!lexer->eof(lexer)) {
      int32_t c = lexer->lookahead;
      advance(lexer);
      if (c == '*' && lexer->lookahead == '/') {
        advance(lexer);
        break;
      }
    }
    return true;
  }
  return false;
}

static bool word_equals(const char *word, const char *keyword) {
  return strcmp(word, keyword) == 0;
}

/*
 * Scans the text of a pragma after its opening brace (the brace is a token of
 * its own), up to but not including the closing brace. The first word tells
 * the kind of the pragma.
 */
static bool scan_pragma_content(TSLexer *lexer, const bool *valid_symbols) {
  char word[16];
  unsigned length = 0;
  while (is_horizontal_space(lexer->lookahead) || is_newline(lexer->lookahead)) skip(lexer);
  while (is_word_char(lexer->lookahead)) {
    if (length < sizeof(word) - 1) word[length++] = (char)to_upper(lexer->lookahead);
    advance(lexer);
  }
  word[length] = '\0';

  enum TokenType kind = GENERIC_PRAGMA;
  if (word_equals(word, "ATTRIBUTE")) {
    kind = ATTRIBUTE_PRAGMA;
  } else if (word_equals(word, "IF") || word_equals(word, "ELSIF") || word_equals(word, "ELSE") ||
             word_equals(word, "END_IF") || word_equals(word, "DEFINE") ||
             word_equals(word, "UNDEFINE")) {
    kind = CONDITIONAL_PRAGMA;
  } else if (word_equals(word, "WARNING") || word_equals(word, "ERROR") ||
             word_equals(word, "INFO") || word_equals(word, "MESSAGE") ||
             word_equals(word, "TEXT")) {
    kind = MESSAGE_PRAGMA;
  } else if (word_equals(word, "REGION") || word_equals(word, "ENDREGION") ||
             word_equals(word, "END_REGION")) {
    kind = REGION_PRAGMA;
  }
  if (!valid_symbols[kind]) return false;

  /* Up to the closing brace; quoted strings may hold a brace, and Beremiz
   * inline C code "{{ ... }}" may hold balanced braces. The quoted values of
   * attributes may span lines ({attribute 'pytmc' := '<newline> pv: X ...'})
   * and hold apostrophes (... we're ...): there a quote ends the string only
   * where the attribute's name or value ends, before ":=" or the closing
   * brace. Elsewhere a quote ends at the end of its line (an apostrophe in a
   * message such as {warning 'don't'} must not swallow the file). An
   * attribute whose string never ends that way (a value being typed) ends at
   * its first inner quote, as if that quote had closed the string. */
  bool attribute = kind == ATTRIBUTE_PRAGMA;
  bool fallback_end = false;
  unsigned depth = 0;
  while (!lexer->eof(lexer)) {
    int32_t c = lexer->lookahead;
    if (c == '{') {
      depth++;
    } else if (c == '}') {
      if (depth == 0) break;
      depth--;
    }
    if (c == '\'' || c == '"') {
      int32_t quote = c;
      advance(lexer);
      for (;;) {
        while (!lexer->eof(lexer) && lexer->lookahead != quote &&
               (attribute || !is_newline(lexer->lookahead))) {
          if (lexer->lookahead == '$') advance(lexer);
          if (!lexer->eof(lexer)) advance(lexer);
        }
        if (lexer->lookahead != quote) break;
        advance(lexer);
        if (!attribute) break;
        /* The blanks after a quote belong to the pragma either way. */
        while (is_horizontal_space(lexer->lookahead) || is_newline(lexer->lookahead)) advance(lexer);
        if (lexer->eof(lexer) || lexer->lookahead == '}' || lexer->lookahead == ':') break;
        if (!fallback_end) {
          lexer->mark_end(lexer);
          fallback_end = true;
        }
      }
      continue;
    }
    advance(lexer);
  }
  if (!(fallback_end && lexer->eof(lexer))) lexer->mark_end(lexer);
  lexer->result_symbol = kind;
  return true;
}

/*
 * After a contextual keyword: decides whether the following text starts a
 * declaration (keyword) or continues a statement (identifier). Statements
 * go on with ":=", ".", "(", "[", "^", ";", "S=", ... while declarations go
 * on with a name, a modifier, a comment, a pragma or a line of their own.
 */
static bool followed_by_declaration(TSLexer *lexer, int token) {
  while (is_horizontal_space(lexer->lookahead) || is_newline(lexer->lookahead)) advance(lexer);
  int32_t c = lexer->lookahead;
  if (lexer->eof(lexer)) return token != KW_AT;
  if (token == KW_AT) return c == '%';
  if (token == KW_OPC) {
    /* A qualifier goes on with another qualifier, a declaration or END_VAR; a variable named
     * OPC with ':', ',' or AT. */
    if (!is_word_start(c)) return c == '{' || c == '(' || c == '/';
    char word[3];
    unsigned length = 0;
    while (is_word_char(lexer->lookahead)) {
      if (length < 2) word[length] = (char)to_upper(lexer->lookahead);
      length++;
      advance(lexer);
    }
    return !(length == 2 && word[0] == 'A' && word[1] == 'T');
  }
  if (c == '{') return true;
  if (c == '(') {
    advance(lexer);
    if (lexer->lookahead == '*') return true;
    /* IEC "TRANSITION (PRIORITY := 1) FROM a TO b" */
    if (token != KW_TRANSITION) return false;
    while (is_horizontal_space(lexer->lookahead)) advance(lexer);
    static const char priority[] = "PRIORITY";
    for (unsigned i = 0; priority[i]; i++) {
      if (to_upper(lexer->lookahead) != priority[i]) return false;
      advance(lexer);
    }
    return !is_word_char(lexer->lookahead);
  }
  if (c == '/') {
    advance(lexer);
    return lexer->lookahead == '/' || lexer->lookahead == '*';
  }
  if (c == ':' && (token == KW_ACTION)) {
    /* "ACTION:" is a label named Action; "ACTION :" never starts an action. */
    return false;
  }
  if (!is_word_start(c)) return false;
  /* A word follows: "S=", "R=" and "REF=" still continue a statement. */
  char word[4];
  unsigned length = 0;
  while (is_word_char(lexer->lookahead)) {
    if (length < 3) word[length] = (char)to_upper(lexer->lookahead);
    length++;
    advance(lexer);
  }
  if (lexer->lookahead == '=') {
    if (length == 1 && (word[0] == 'S' || word[0] == 'R')) return false;
    if (length == 3 && word[0] == 'R' && word[1] == 'E' && word[2] == 'F') return false;
  }
  return true;
}

/* Words that start a Structured Text statement and never an IL instruction. */
static bool is_st_statement_keyword(const char *word) {
  return word_equals(word, "IF") || word_equals(word, "CASE") || word_equals(word, "FOR") ||
         word_equals(word, "WHILE") || word_equals(word, "REPEAT");
}

/* Skips a string literal; the lookahead is on its opening quote. */
static void skip_string(TSLexer *lexer) {
  int32_t quote = lexer->lookahead;
  advance(lexer);
  while (!lexer->eof(lexer) && lexer->lookahead != quote && !is_newline(lexer->lookahead)) {
    if (lexer->lookahead == '$') advance(lexer);
    if (!lexer->eof(lexer)) advance(lexer);
  }
  if (lexer->lookahead == quote) advance(lexer);
}

/*
 * Reads on to the end of the line (or, with `until_close`, to the ')' that closes an already
 * opened parenthesis, across lines) and tells whether a ';' stands there outside comments and
 * strings. IL never uses ';': a line that has one is Structured Text.
 */
static bool rest_has_semicolon(TSLexer *lexer, bool until_close) {
  unsigned depth = until_close ? 1 : 0;
  unsigned budget = 4096; /* a runaway '(' must not scan the whole file */
  while (!lexer->eof(lexer) && budget-- > 0) {
    int32_t c = lexer->lookahead;
    if (is_newline(c) && !until_close) return false;
    if (c == '(' || c == '/') {
      if (skip_comment(lexer)) continue;
      if (c == '(') depth++;
      continue;
    }
    if (c == '\'' || c == '"') {
      skip_string(lexer);
      continue;
    }
    advance(lexer);
    if (c == ';') return !until_close || depth == 0;
    if (c == ')' && depth > 0 && --depth == 0 && until_close) {
      while (is_horizontal_space(lexer->lookahead) || is_newline(lexer->lookahead)) advance(lexer);
      return lexer->lookahead == ';';
    }
  }
  return false;
}

/* Reads a word into `word` (upper case, cut to `size` - 1 characters); returns its full length. */
static unsigned read_word(TSLexer *lexer, char *word, unsigned size) {
  unsigned length = 0;
  while (is_word_char(lexer->lookahead)) {
    if (length < size - 1) word[length] = (char)to_upper(lexer->lookahead);
    length++;
    advance(lexer);
  }
  word[length < size ? length : size - 1] = '\0';
  return length;
}

/* After a word: whether it is "S=", "R=" or "REF=", the ExST assignments. */
static bool is_set_reset_assignment(TSLexer *lexer, const char *word, unsigned length) {
  if (lexer->lookahead != '=') return false;
  return (length == 1 && (word[0] == 'S' || word[0] == 'R')) || (length == 3 && word_equals(word, "REF"));
}

/*
 * At the start of the line after an IL line: whether that line is a Structured Text statement
 * (IF/CASE/FOR/WHILE/REPEAT, "name :=", "name S=", or a call "name(...);"). Then the line
 * before it was an ST statement that lacks its ';' ("Foo" NEWLINE "Bar();") rather than an IL
 * instruction: refusing the IL line end there lets error recovery find the missing ';' and keep
 * the body one statement list. Declaration lines and expression fragments ("x AT %IX1 : BOOL;",
 * "%IW2;") are not statements. Only looks ahead (the token's end is already marked); the
 * lookahead is on the first character of the next line that is not blank.
 */
static bool next_line_is_st(TSLexer *lexer) {
  /* A comment first: no (refusing the line end would leave the comment to the internal lexer,
   * which does not know comments). */
  if (!is_word_start(lexer->lookahead)) return false;
  char word[8];
  unsigned length = read_word(lexer, word, sizeof(word));
  if (length < sizeof(word) && is_st_statement_keyword(word)) return true;
  /* The rest of a reference: .member, [index], ^ */
  for (;;) {
    while (is_horizontal_space(lexer->lookahead)) advance(lexer);
    int32_t c = lexer->lookahead;
    if (c == '.') {
      advance(lexer);
      while (is_horizontal_space(lexer->lookahead)) advance(lexer);
      char member[2];
      if (read_word(lexer, member, sizeof(member)) == 0) return false;
    } else if (c == '[') {
      while (!lexer->eof(lexer) && lexer->lookahead != ']' && !is_newline(lexer->lookahead)) advance(lexer);
      if (lexer->lookahead != ']') return false;
      advance(lexer);
    } else if (c == '^') {
      advance(lexer);
    } else {
      break;
    }
  }
  int32_t c = lexer->lookahead;
  if (c == ':') {
    advance(lexer);
    return lexer->lookahead == '=';
  }
  if (c == '(') {
    advance(lexer);
    if (lexer->lookahead == '*') return false; /* a comment: not a call */
    return rest_has_semicolon(lexer, true);
  }
  if (is_word_start(c)) {
    length = read_word(lexer, word, sizeof(word));
    return is_set_reset_assignment(lexer, word, length);
  }
  return false;
}

/*
 * Whether an IL operand that is not a name starts here, on the operator's line: a literal or an
 * address, and the line has no ';' (which only Structured Text uses: "RETURN 1;"). Zero width
 * (the end is marked before looking), so that the token never stands in the way of the ST reading
 * of a line. Names are handled by scan_word.
 */
static bool starts_il_operand(TSLexer *lexer) {
  lexer->mark_end(lexer);
  int32_t c = lexer->lookahead;
  bool operand = (c >= '0' && c <= '9') || c == '%' || c == '\'' || c == '"' || c == '-' || c == '+';
  return operand && !rest_has_semicolon(lexer, false);
}

/*
 * On a ';' inside an argument list: whether the same line goes on with more arguments and the
 * ')' that closes the list ("SHL(in_word;n)"), so that the ';' stands for ','. A ';' followed by
 * the end of the line ends a statement whose ')' is missing.
 */
static bool semicolon_separates_arguments(TSLexer *lexer) {
  advance(lexer);
  lexer->mark_end(lexer);
  unsigned depth = 1;
  bool argument = false;
  while (!lexer->eof(lexer) && !is_newline(lexer->lookahead)) {
    int32_t c = lexer->lookahead;
    if (c == '(' || c == '/') {
      if (skip_comment(lexer)) continue;
      if (c == '(') depth++;
      argument = true;
      continue;
    }
    if (c == '\'' || c == '"') {
      skip_string(lexer);
      argument = true;
      continue;
    }
    advance(lexer);
    if (c == ';') return false;
    if (c == ')' && --depth == 0) return argument;
    if (!is_horizontal_space(c)) argument = true;
  }
  return false;
}

/* Declaration keywords that are taken as keywords at the start of a line even
 * where the grammar does not expect them (an unterminated IF before the next
 * METHOD): error recovery then sees the header instead of two identifiers. */
static bool is_header_keyword(int token) {
  return token == KW_METHOD || token == KW_PROPERTY || token == KW_ACTION ||
         token == KW_INTERFACE || token == KW_CLASS || token == KW_NAMESPACE;
}

/* A name follows on the same line. */
static bool followed_by_name(TSLexer *lexer) {
  while (is_horizontal_space(lexer->lookahead)) advance(lexer);
  return is_word_start(lexer->lookahead);
}

/*
 * Reads a word (upper case into `word`, cut to `size` - 1 characters; its full length into
 * `length`) and returns the contextual keyword among `candidates` (one bit per SOFT_KEYWORDS
 * entry) that it spells, or -1. With `stop_early` the reading stops as soon as no candidate
 * starts with the characters read: the caller then needs nothing else of the word, and most
 * names are told apart from every keyword after a character or two (every character costs a
 * call into the tree-sitter lexer).
 */
static int read_soft_keyword(TSLexer *lexer, uint32_t candidates, bool stop_early, char *word,
                             unsigned size, unsigned *length) {
  unsigned n = 0;
  while (is_word_char(lexer->lookahead)) {
    int32_t c = to_upper(lexer->lookahead);
    for (unsigned i = 0; i < SOFT_KEYWORD_COUNT; i++) {
      /* The terminating NUL never equals a word character: a keyword shorter than the word drops out. */
      if ((candidates & (1u << i)) && SOFT_KEYWORDS[i][n] != c) candidates &= ~(1u << i);
    }
    if (n < size - 1) word[n] = (char)c;
    n++;
    advance(lexer);
    if (stop_early && candidates == 0) break;
  }
  word[n < size ? n : size - 1] = '\0';
  *length = n;
  for (unsigned i = 0; i < SOFT_KEYWORD_COUNT; i++) {
    if ((candidates & (1u << i)) && SOFT_KEYWORDS[i][n] == '\0') return KW_METHOD + (int)i;
  }
  return -1;
}

/*
 * A word: a contextual keyword where one is valid, or else, right after an IL operator on the
 * same line, the zero-width mark that an operand follows (`operand_valid`).
 */
static bool scan_word(TSLexer *lexer, const bool *valid_symbols, bool saw_newline, bool operand_valid) {
  /* The keywords this word may be: those valid here, and the header keywords, which are taken at
     the start of a line even where they are not valid (see is_header_keyword). */
  uint32_t candidates = 0;
  bool initial_matches = false;
  int32_t initial = to_upper(lexer->lookahead);
  for (unsigned i = 0; i < SOFT_KEYWORD_COUNT; i++) {
    int token = KW_METHOD + (int)i;
    if (!valid_symbols[token] && !is_header_keyword(token)) continue;
    candidates |= 1u << i;
    initial_matches = initial_matches || SOFT_KEYWORDS[i][0] == initial;
  }
  /* Most words are names the internal lexer reads anyway: when no keyword that may stand here
     starts with this letter and no IL operand may follow, there is nothing to do. */
  if (!operand_valid && !initial_matches) return false;
  if (operand_valid) lexer->mark_end(lexer);
  char word[24];
  unsigned length = 0;
  int token = read_soft_keyword(lexer, candidates, !operand_valid, word, sizeof(word), &length);
  if (token >= 0 && valid_symbols[token]) {
    lexer->mark_end(lexer);
    if (!followed_by_declaration(lexer, token)) return false;
    lexer->result_symbol = token;
    return true;
  }
  /* At the start of a line: after a newline, or at column 0 (the word is ASCII, so its length in
     characters is the column it ends at). get_column() re-reads the line from its start, so it
     is asked only for the rare header keyword, not for every word. */
  if (token >= 0 && (saw_newline || lexer->get_column(lexer) == length)) {
    lexer->mark_end(lexer);
    if (!followed_by_name(lexer)) return false;
    lexer->result_symbol = token;
    return true;
  }
  if (!operand_valid || is_set_reset_assignment(lexer, word, length) || rest_has_semicolon(lexer, false)) {
    return false;
  }
  lexer->result_symbol = IL_SAME_LINE;
  return true;
}

bool tree_sitter_iec61131_external_scanner_scan(void *payload, TSLexer *lexer,
                                                const bool *valid_symbols) {
  (void)payload;
  bool error_recovery = valid_symbols[ERROR_SENTINEL];
  bool newline_valid = valid_symbols[IL_NEWLINE] && !error_recovery;
  bool saw_newline = false;

  /* Just after the "{" of a pragma (never valid elsewhere). */
  if (!error_recovery && (valid_symbols[ATTRIBUTE_PRAGMA] || valid_symbols[GENERIC_PRAGMA])) {
    return scan_pragma_content(lexer, valid_symbols);
  }

  for (;;) {
    int32_t c = lexer->lookahead;
    if (is_newline(c)) {
      saw_newline = true;
      skip(lexer);
    } else if (is_horizontal_space(c)) {
      skip(lexer);
    } else {
      break;
    }
  }

  if (newline_valid && (saw_newline || lexer->eof(lexer))) {
    lexer->mark_end(lexer);
    if (saw_newline && next_line_is_st(lexer)) return false;
    lexer->result_symbol = IL_NEWLINE;
    return true;
  }

  if (lexer->eof(lexer)) return false;

  int32_t c = lexer->lookahead;
  if (c == ';' && valid_symbols[ARGUMENT_SEMICOLON] && !error_recovery) {
    if (!semicolon_separates_arguments(lexer)) return false;
    lexer->result_symbol = ARGUMENT_SEMICOLON;
    return true;
  }
  bool operand_valid = valid_symbols[IL_SAME_LINE] && !error_recovery && !saw_newline;
  if (operand_valid && !is_word_start(c) && starts_il_operand(lexer)) {
    lexer->result_symbol = IL_SAME_LINE;
    return true;
  }
  if (c == '(' || c == '/') {
    /* An unclosed comment runs to the end of the file (the syntax checks report it). */
    if (!skip_comment(lexer)) return false;
    lexer->mark_end(lexer);
    lexer->result_symbol = COMMENT;
    return true;
  }
  if (is_word_start(c)) {
    return scan_word(lexer, valid_symbols, saw_newline, operand_valid);
  }
  return false;
}
