#include "checker/semantic/address_checker.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "checker/semantic/type_size.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

SyntaxNode address_node(const Symbol& variable) {
  return variable.location_node ? variable.location_node.child_by_field("address") : SyntaxNode();
}

// `a, b AT %IX0.0 : BOOL` makes one Symbol per name, all on one declaration node.
std::vector<SyntaxNode> declaration_names(const Symbol& variable) {
  return variable.node.children_by_field("name");
}

bool is_first_name(const Symbol& variable) {
  const std::vector<SyntaxNode> names = declaration_names(variable);
  return names.empty() || names.front().range().begin == variable.name_range.begin;
}

// What classify_address_type needs to know about a declared type; nullopt when the type is not
// known well enough to judge (unresolved names, generics, references).
struct TypeShape {
  TypeCategory category = TypeCategory::Elementary;
  uint32_t bits = 0;  // elementary types; 0 = unknown
};

std::optional<TypeShape> shape_of(const Type* type) {
  const Type* base = underlying(type);
  if (!base) return std::nullopt;
  switch (base->kind) {
    case TypeKind::Unknown:
    case TypeKind::Void:
    case TypeKind::Generic:
    case TypeKind::Null:
    case TypeKind::Reference: return std::nullopt;
    case TypeKind::Bool: return TypeShape{TypeCategory::Boolean, 1};
    case TypeKind::Array:
    case TypeKind::Struct:
    case TypeKind::Union:
    case TypeKind::String:
    case TypeKind::WString:
    case TypeKind::Pou: return TypeShape{TypeCategory::NotElementary, 0};
    default: {
      const Type* arithmetic = arithmetic_type(base);  // an enum or subrange is its base type
      return TypeShape{TypeCategory::Elementary, arithmetic ? arithmetic->bits : 0};
    }
  }
}

std::string_view size_words(AddressSize size) {
  switch (size) {
    case AddressSize::None:
    case AddressSize::Bit: return "a single bit";
    case AddressSize::Byte: return "a byte";
    case AddressSize::Word: return "a word (16 bits)";
    case AddressSize::Double: return "a double word (32 bits)";
    case AddressSize::Long: return "a long word (64 bits)";
  }
  return "an address";
}

// The size letter an elementary type of `bits` needs; 0 when no address size has that many bits.
char letter_for_bits(uint32_t bits) {
  switch (bits) {
    case 8: return 'B';
    case 16: return 'W';
    case 32: return 'D';
    case 64: return 'L';
    default: return 0;
  }
}

std::string bytes_text(uint64_t first, uint64_t last) {
  return first == last ? fmt::format("byte {}", first) : fmt::format("bytes {}..{}", first, last);
}

// Where a located variable lies, for messages: "bit 2.3" or "bytes 4..7".
std::string extent_text(const LocatedVariable& located) {
  const DirectAddress& address = located.address;
  if (address.is_bit()) return fmt::format("bit {}.{}", address.first_byte, address.bit.value_or(0));
  const uint64_t bytes = located.size_bytes != 0 ? located.size_bytes : address.last_byte - address.first_byte + 1;
  return bytes_text(address.first_byte, address.first_byte + bytes - 1);
}

uint64_t size_in_bytes(const ProjectModel& model, const Symbol& variable) {
  std::optional<TypeLayout> layout = type_layout(model, model.type_of(&variable));
  return layout ? layout->size : 0;
}

class AddressChecker {
 public:
  AddressChecker(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out)
      : model_(model), source_(source), out_(out) {}

  void run() {
    for (const Symbol& symbol : model_.source(source_).symbols.storage) {
      if (symbol.kind == SymbolKind::Variable && symbol.location_node) check_declaration(symbol);
    }
    report_overlaps();
    check_addresses_in_code();
  }

 private:
  void report(std::string_view code, std::string message, TextRange range, std::string help = {},
              std::vector<DiagnosticLabel> labels = {}) {
    out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help), std::move(labels)));
  }

  void check_declaration(const Symbol& variable) {
    const SyntaxNode node = address_node(variable);
    if (!node) return;
    const std::string_view text = node.text();
    const DirectAddressResult parsed = parse_direct_address(text, model_.profile().addressing);
    if (!is_first_name(variable)) {
      // Reported once, at the second name: the first one is the variable the address was meant for.
      const std::vector<SyntaxNode> names = declaration_names(variable);
      if (names.size() > 1 && names[1].range().begin == variable.name_range.begin) {
        report(codes::kInvalidAddress,
               fmt::format("{} variables are declared AT one address '{}': an address belongs to one variable",
                           names.size(), text),
               node.range(), "declare each variable on its own line with its own address");
      }
      return;
    }
    if (!parsed.ok()) {
      report(codes::kInvalidAddress, fmt::format("'{}': {}", text, parsed.error), node.range());
      return;
    }
    const DirectAddress& address = *parsed.address;
    if (address.wildcard) {
      check_incomplete(variable, address, node);
      return;
    }
    check_fit(variable, address, node);
  }

  // `%MX0.8 := TRUE;`: an address written in code must exist as much as a declared one (AK800
  // manual L970, L1017). AT locations are checked above, VAR_CONFIG and VAR_ACCESS paths by the
  // configuration checker, and `x.%X3` is a bit of a variable, not an address.
  void check_addresses_in_code() {
    const Source& source = model_.source(source_);
    if (source.library || !source.document->tree()) return;
    // Every direct address has a '%': most files have none, and then there is nothing to walk.
    if (source.document->tree()->text().find('%') == std::string::npos) return;
    walk_preorder(source.document->tree()->root(), [&](SyntaxNode node) {
      if (node.kind() != "direct_variable") return true;
      const SyntaxNode parent = node.parent();
      const std::string_view context = parent ? parent.kind() : std::string_view();
      if (context == "location" || context == "member_expression" || context == "access_path") return false;
      const DirectAddressResult parsed = parse_direct_address(node.text(), model_.profile().addressing);
      if (!parsed.ok()) {
        report(codes::kInvalidAddress, fmt::format("'{}': {}", node.text(), parsed.error), node.range());
      }
      return false;
    });
  }

  // `%I*` / `%Q*` are completed per instance by VAR_CONFIG (MP300 manual L11596-11654).
  void check_incomplete(const Symbol& variable, const DirectAddress& address, SyntaxNode node) {
    const Symbol* owner = variable.owner;
    if (variable.section == ast::VarSection::Config) {
      report(codes::kInvalidAddress,
             fmt::format("'{}' is incomplete: VAR_CONFIG must give the complete address", node.text()), node.range(),
             fmt::format("write the location, e.g. %{}X0.0", area_letter(address.area)));
    } else if (owner && (owner->kind == SymbolKind::Function || owner->kind == SymbolKind::Method)) {
      report(codes::kInvalidAddress,
             fmt::format("'{}' in a {}: VAR_CONFIG completes an incomplete address per instance, and a {} has none",
                         node.text(), symbol_kind_name(owner->kind), symbol_kind_name(owner->kind)),
             node.range(), "declare the variable in a FUNCTION_BLOCK or PROGRAM");
    }
  }

  void check_fit(const Symbol& variable, const DirectAddress& address, SyntaxNode node) {
    const Type* type = model_.type_of(&variable);
    const std::optional<TypeShape> shape = shape_of(type);
    if (!shape) return;
    const Profile& profile = model_.profile();
    const std::string address_text = format_direct_address(address);
    switch (classify_address_type(address, shape->bits, shape->category)) {
      case AddressFit::Fits: return;
      case AddressFit::Mismatch: {
        const char letter = letter_for_bits(shape->bits);
        report(codes::kAddressTypeMismatch,
               fmt::format("'{}' is {}, but {} is a single bit: only BOOL fits a bit address", variable.name,
                           type->name, address_text),
               node.range(),
               letter != 0 ? fmt::format("use a {}-bit address (%{}{}…) or declare '{}' as BOOL", shape->bits,
                                         area_letter(address.area), letter, variable.name)
                           : fmt::format("use a byte address (%{}B…) as its start, or declare '{}' as BOOL",
                                         area_letter(address.area), variable.name));
        return;
      }
      case AddressFit::StartAddress:
        if (!profile.compound_types_at_addresses) {
          report(codes::kAddressTypeMismatch,
                 fmt::format("'{}' is {}: this profile maps only elementary types to addresses", variable.name,
                             type->name),
                 node.range(), "declare the elements one by one, each AT its own address");
        }
        return;
      case AddressFit::SizeDiffers:
        if (shape->category == TypeCategory::Boolean && !profile.address_size_mismatch_is_error) {
          return;  // CODESYS: a BOOL at a byte/word address takes one whole byte (MP300 L10851-10853)
        }
        report_size_difference(variable, *type, *shape, address, node);
        return;
    }
  }

  void report_size_difference(const Symbol& variable, const Type& type, const TypeShape& shape,
                              const DirectAddress& address, SyntaxNode node) {
    if (shape.category == TypeCategory::Boolean) {
      report(codes::kAddressTypeMismatch,
             fmt::format("'{}' is {}, but {} is {}: a BOOL belongs at a bit address", variable.name, type.name,
                         format_direct_address(address), size_words(address.size)),
             node.range(),
             fmt::format("use a bit address such as %{}X{}.0", area_letter(address.area), address.first_byte));
      return;
    }
    const uint64_t bytes = std::max<uint64_t>(1, shape.bits / 8);
    const std::string where =
        shape.bits > address.size_bits()
            ? fmt::format("it starts there and covers {}",
                          bytes_text(address.first_byte, address.first_byte + bytes - 1))
            : fmt::format("it uses only {}", bytes_text(address.first_byte, address.first_byte + bytes - 1));
    const char letter = letter_for_bits(shape.bits);
    Diagnostic diagnostic = make_diagnostic(
        codes::kAddressTypeMismatch,
        fmt::format("'{}' is {} ({} bits), but {} is {}: {}", variable.name, type.name, shape.bits,
                    format_direct_address(address), size_words(address.size), where),
        node.range(),
        letter != 0 ? fmt::format("use a %{}{}… address for a {}-bit type, or the type that matches the address",
                                  area_letter(address.area), letter, shape.bits)
                    : std::string("use the type that matches the address"));
    // CODESYS reads the address as the start of the variable (AK800 manual L1200 maps a REAL on
    // %MW200 this way): legal there, so a warning; the IEC and OpenPCS profiles reject it.
    if (!model_.profile().address_size_mismatch_is_error) diagnostic.severity = Severity::Warning;
    out_.push_back(std::move(diagnostic));
  }

  void report_overlaps() {
    const AddressTable& table = model_.address_table();
    for (const AddressOverlap& overlap : table.overlaps) {
      const Symbol& later = *table.variables[overlap.second];
      if (later.source != source_) continue;
      const Symbol& earlier = *table.variables[overlap.first];
      const LocatedVariable& here = table.located[overlap.second];
      const LocatedVariable& there = table.located[overlap.first];
      std::string message =
          fmt::format("'{}' AT {} ({}) overlaps '{}' AT {} ({}): both use {} of %{}", later.name,
                      format_direct_address(here.address), extent_text(here), earlier.name,
                      format_direct_address(there.address), extent_text(there),
                      here.address.is_bit() && there.address.is_bit()
                          ? fmt::format("bit {}.{}", here.address.first_byte, here.address.bit.value_or(0))
                          : bytes_text(overlap.first_shared_byte, overlap.last_shared_byte),
                      area_letter(here.address.area));
      std::vector<DiagnosticLabel> labels;
      if (earlier.source == source_) {
        labels.push_back({earlier.name_range, fmt::format("'{}' is declared here", earlier.name)});
      } else {
        // A label can only point into the file being reported; name the other file instead.
        const Document& other = *model_.source(earlier.source).document;
        message += fmt::format(" ('{}' is declared in {}:{})", earlier.name, other.path(),
                               other.position_of_tree_offset(earlier.name_range.begin).line);
      }
      const SyntaxNode node = address_node(later);
      report(codes::kAddressOverlap, std::move(message), node ? node.range() : later.name_range,
             "move one of them to free bytes; for a deliberate overlay set E504 = \"off\" in rung.toml [diagnostics]",
             std::move(labels));
    }
  }

  const ProjectModel& model_;
  SourceId source_;
  std::vector<Diagnostic>& out_;
};

}  // namespace

std::optional<DirectAddress> declared_address(const ProjectModel& model, const Symbol& variable) {
  const SyntaxNode node = address_node(variable);
  if (!node) return std::nullopt;
  DirectAddressResult parsed = parse_direct_address(node.text(), model.profile().addressing);
  return std::move(parsed.address);
}

AddressTable build_address_table(const ProjectModel& model) {
  AddressTable table;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    const Source& source = model.source(id);
    if (source.library) continue;
    std::vector<const Symbol*> declared;
    for (const Symbol& symbol : source.symbols.storage) {
      // One entry per declaration: `a, b AT %IX0.0` is E505, not also an overlap of a and b.
      if (symbol.kind == SymbolKind::Variable && symbol.location_node && is_first_name(symbol)) {
        declared.push_back(&symbol);
      }
    }
    std::sort(declared.begin(), declared.end(),
              [](const Symbol* a, const Symbol* b) { return a->name_range.begin < b->name_range.begin; });
    for (const Symbol* variable : declared) {
      std::optional<DirectAddress> address = declared_address(model, *variable);
      if (!address || address->wildcard) continue;
      table.variables.push_back(variable);
      table.located.push_back(LocatedVariable{std::string(variable->name), variable->name_range, std::move(*address),
                                              size_in_bytes(model, *variable)});
    }
  }
  table.overlaps = find_address_overlaps(table.located);
  // Inputs are read-only (MP300 manual L10826), so variables sharing an input never change each
  // other; the manual's own VAR_CONFIG example reads %IX1.0 in two instances (L11660-11664).
  std::erase_if(table.overlaps, [&](const AddressOverlap& overlap) {
    return table.located[overlap.first].address.area == AddressArea::Input;
  });
  return table;
}

void check_addresses(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  AddressChecker(model, source, out).run();
}

}  // namespace rung::check
