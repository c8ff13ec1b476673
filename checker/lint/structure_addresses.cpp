// L010 direct-address-in-code: %I, %Q and %M addresses written in statements. A declaration
// (AT %IX0.0) gives an address its name once; the checker reports addresses that are invalid
// (E505), this rule the valid ones that should have a name.
#include <fmt/format.h>

#include "checker/lint/structure_pou.hpp"
#include "checker/lint/structure_rules.hpp"
#include "checker/semantic/direct_address.hpp"

namespace rung::lint::structure {
namespace {

// The elementary type that fits the address, for the example in the help.
std::string_view type_for(const check::DirectAddress& address) {
  switch (address.size) {
    case check::AddressSize::Byte: return "BYTE";
    case check::AddressSize::Word: return "WORD";
    case check::AddressSize::Double: return "DWORD";
    case check::AddressSize::Long: return "LWORD";
    default: return "BOOL";
  }
}

}  // namespace

void check_direct_address(LintContext& context) {
  // Every direct address has a '%': most files have none.
  if (context.text().find('%') == std::string_view::npos) return;
  const check::AddressingMode mode = context.model().profile().addressing;
  const NodeList& nodes = context.nodes();
  static const TSFieldId kMember = NodeList::field_id("member");
  for (const check::Symbol* pou : context.pous()) {
    for (SyntaxNode body : bodies_of(*pou)) {
      nodes.walk(nodes.index_of(body), [&](uint32_t i) {
        if (nodes.is_extra(i)) return false;
        if (nodes.kind(i) != "direct_variable") return nodes.has_children(i);
        // x.%X3 is a bit of the variable x, not an address.
        const uint32_t parent = nodes.parent(i);
        if (parent != NodeList::kNone && nodes.kind(parent) == "member_expression" &&
            nodes.child_by_field(parent, kMember) == i) {
          return false;
        }
        const SyntaxNode node = nodes.node(i);
        const check::DirectAddressResult parsed = check::parse_direct_address(node.text(), mode);
        if (!parsed.ok() || parsed.address->wildcard) return false;  // E505 reports those
        context.report("L010", fmt::format("direct address {} in code: give it a name in a declaration", node.text()),
                       node.range(),
                       fmt::format("declare it once, e.g. Signal AT {} : {}; and use the name: it says what the "
                                   "signal is, and a rewiring changes one line",
                                   node.text(), type_for(*parsed.address)));
        return false;
      });
    }
  }
}

}  // namespace rung::lint::structure
