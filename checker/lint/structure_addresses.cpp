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
  for (const check::Symbol* pou : context.pous()) {
    for (SyntaxNode body : bodies_of(*pou)) {
      walk_preorder(body, [&](SyntaxNode node) {
        if (node.is_extra()) return false;
        if (node.kind() != "direct_variable") return node.child_count() > 0;
        // x.%X3 is a bit of the variable x, not an address.
        const SyntaxNode parent = node.parent();
        if (parent && parent.kind() == "member_expression" && parent.child_by_field("member") == node) return false;
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
