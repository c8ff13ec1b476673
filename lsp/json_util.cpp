#include "lsp/json_util.hpp"

namespace rung::lsp {

const Json& json_at(const Json& root, std::initializer_list<const char*> keys) {
  static const Json kNull;
  const Json* node = &root;
  for (const char* key : keys) {
    if (!node->is_object()) return kNull;
    const auto found = node->find(key);
    if (found == node->end()) return kNull;
    node = &*found;
  }
  return *node;
}

std::string json_string(const Json& object, const char* key) {
  if (!object.is_object()) return {};
  const auto found = object.find(key);
  return found != object.end() && found->is_string() ? found->get<std::string>() : std::string();
}

}  // namespace rung::lsp
