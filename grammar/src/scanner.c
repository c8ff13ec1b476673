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
};
#define SOFT_KEYWORD_COUNT (sizeof(SOFT_KEYWORDS) / sizeof(SOFT_KEYWORDS[0]))



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

/* Scans a "(* ... *)" comment (nested) after the opening "(" was consumed. */
static bool scan_paren_comment(TSLexer *lexer) {
  if (lexer->lookahead != '*') return false;
  advance(lexer);
  unsigned depth = 1;
  while (!lexer->eof(lexer)) {
    int32_t c = lexer->lookahead;
    if (c == '*') {
      advance(lexer);
      if (lexer->lookahead == ')') {
        advance(lexer);
        if (--depth == 0) break;
      }
    } else if (c == '(') {
      advance(lexer);
      if (lexer->lookahead == '*') {
        advance(lexer);
        depth++;
      }
    } else {
      advance(lexer);
    }
  }
  lexer->mark_end(lexer);
  lexer->result_symbol = COMMENT;
  return true;
}

/* Scans "// ..." or a C block comment after the opening "/" was consumed. */
static bool scan_slash_comment(TSLexer *lexer) {
  if (lexer->lookahead == '/') {
    while (!lexer->eof(lexer) && !is_newline(lexer->lookahead)) advance(lexer);
  } else if (lexer->lookahead == '*') {
    advance(lexer);
    while (!lexer->eof(lexer)) {
      if (lexer->lookahead == '*') {
        advance(lexer);
        if (lexer->lookahead == '/') {
          advance(lexer);
          break;
        }
      } else {
        advance(lexer);
      }
    }
  } else {
    return false;
  }
  lexer->mark_end(lexer);
  lexer->result_symbol = COMMENT;
  return true;
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
   * attributes may span lines ({attribute 'pytmc' := '<newline> pv: X ...'});
   * elsewhere a quote ends at the end of its line (an apostrophe in a
   * message such as {warning 'don't'} must not swallow the file). */
  bool multiline_quotes = kind == ATTRIBUTE_PRAGMA;
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
      while (!lexer->eof(lexer) && lexer->lookahead != quote &&
             (multiline_quotes || !is_newline(lexer->lookahead))) {
        if (lexer->lookahead == '$') advance(lexer);
        if (!lexer->eof(lexer)) advance(lexer);
      }
      if (lexer->lookahead == quote) advance(lexer);
      continue;
    }
    advance(lexer);
  }
  lexer->mark_end(lexer);
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

static bool scan_word(TSLexer *lexer, const bool *valid_symbols, bool at_line_start) {
  char word[24];
  unsigned length = 0;
  while (is_word_char(lexer->lookahead)) {
    if (length >= sizeof(word) - 1) return false;
    word[length++] = (char)to_upper(lexer->lookahead);
    advance(lexer);
  }
  word[length] = '\0';
  if (length < 2) return false;
  for (unsigned i = 0; i < SOFT_KEYWORD_COUNT; i++) {
    int token = KW_METHOD + (int)i;
    if (!word_equals(word, SOFT_KEYWORDS[i])) continue;
    if (valid_symbols[token]) {
      lexer->mark_end(lexer);
      if (!followed_by_declaration(lexer, token)) return false;
      lexer->result_symbol = token;
      return true;
    }
    if (at_line_start && is_header_keyword(token)) {
      lexer->mark_end(lexer);
      if (!followed_by_name(lexer)) return false;
      lexer->result_symbol = token;
      return true;
    }
    return false;
  }
  return false;
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
    lexer->result_symbol = IL_NEWLINE;
    return true;
  }

  if (lexer->eof(lexer)) return false;

  int32_t c = lexer->lookahead;
  if (c == '(') {
    advance(lexer);
    return scan_paren_comment(lexer);
  }
  if (c == '/') {
    advance(lexer);
    return scan_slash_comment(lexer);
  }
  if (is_word_start(c)) {
    return scan_word(lexer, valid_symbols, saw_newline || lexer->get_column(lexer) == 0);
  }
  return false;
}
