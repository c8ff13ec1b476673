#include "lsp/features/features.hpp"

namespace rung::lsp {

void register_features(Router& router) {
  register_diagnostics(router);
  register_navigation(router);
  register_symbols(router);
  register_hierarchy(router);
  register_completion(router);
  register_hover(router);
  register_presentation(router);
  register_formatting(router);
  register_code_actions(router);
}

}  // namespace rung::lsp
