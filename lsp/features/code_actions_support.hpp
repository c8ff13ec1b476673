// What every code action of rung has in common: the request it answers (document, range, the
// diagnostics the client sent, the kinds it asked for) and the LSP shape of an action (a
// CodeAction literal with a WorkspaceEdit on that document).
#pragma once

#include <string>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {

// CodeActionKind values rung offers.
inline constexpr std::string_view kQuickFix = "quickfix";
inline constexpr std::string_view kRefactorRewrite = "refactor.rewrite";
inline constexpr std::string_view kFixAll = "source.fixAll.rung";
// "Fix all findings of one rule" is a source action of its own kind, so that an editor's
// "fix all on save" (source.fixAll) applies the whole-file fix only once.
inline constexpr std::string_view kFixRule = "source.rung.fixRule";

class ActionRequest {
 public:
  ActionRequest(Session& session, const DocumentRef& document, TextRange range, const Json& context);

  Session& session() const { return session_; }
  const DocumentRef& document() const { return document_; }
  TextRange range() const { return range_; }  // FILE coordinates
  // Whether the client wants actions of `kind` (context.only: a kind or a parent of it).
  bool wants(std::string_view kind) const;
  // Whether the client asked for a kind explicitly (context.only names it or a child of it).
  bool asks_for(std::string_view kind) const;
  // Whether `range` (FILE coordinates) touches the requested range.
  bool touches(TextRange range) const;

  // Adds a CodeAction whose edits (FILE coordinates of the document) fix `diagnostic_code` at
  // `diagnostic_range` (empty code: no diagnostic); the client's own diagnostic objects of that
  // code and range are attached, as the protocol asks.
  void add(std::string title, std::string_view kind, const std::vector<lint::TextEdit>& edits,
           std::string_view diagnostic_code = {}, TextRange diagnostic_range = {}, bool preferred = false);

  Json take() { return std::move(actions_); }

 private:
  Json workspace_edit(const std::vector<lint::TextEdit>& edits) const;

  Session& session_;
  DocumentRef document_;
  TextRange range_;
  Json client_diagnostics_ = Json::array();
  std::vector<std::string> only_;
  bool document_changes_ = false;
  Json actions_ = Json::array();
};

// The groups of actions, each in its own file.
void add_lint_actions(ActionRequest& request);     // code_actions_lint.cpp
void add_checker_actions(ActionRequest& request);  // code_actions_checker.cpp
void add_refactorings(ActionRequest& request);     // code_actions_refactor.cpp

}  // namespace rung::lsp
