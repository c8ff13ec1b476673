#include "checker/lint/node_list.hpp"

namespace rung::lint {

std::string_view operator_text(const NodeList& nodes, uint32_t i) {
  static const TSFieldId kOperator = NodeList::field_id("operator");
  if (const uint32_t op = nodes.child_by_field(i, kOperator); op != NodeList::kNone) return nodes.text(op);
  std::string_view found;
  bool done = false;
  nodes.for_each_child(i, [&](uint32_t child) {
    if (done || nodes.is_named(child) || nodes.is_extra(child)) return;
    found = nodes.text(child);
    done = true;
  });
  return found;
}

}  // namespace rung::lint
