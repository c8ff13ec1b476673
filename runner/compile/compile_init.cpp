// Initial values: the bytes every variable starts with, written into the memory image (globals,
// program instances), into FB instance templates and into call frames. Constant initial values
// are written at compile time; the standard's defaults apply where none is given (zero, an
// enumeration's first value or declared default, a subrange's lower bound, a structure's field
// initialisers).
#include <algorithm>
#include <cstring>

#include "checker/semantic/body_checker.hpp"
#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/stdlib/text.hpp"

namespace rung::run {
namespace {

constexpr int kMaxDepth = 48;

void put(std::vector<uint8_t>& bytes, uint64_t at, const void* data, size_t size) {
  if (at + size > bytes.size()) bytes.resize(at + size, 0);
  std::memcpy(bytes.data() + at, data, size);
}

void put_integer(std::vector<uint8_t>& bytes, uint64_t at, uint64_t value, size_t size) {
  uint8_t raw[8];
  for (size_t i = 0; i < 8; ++i) raw[i] = static_cast<uint8_t>(value >> (8 * i));
  put(bytes, at, raw, size);
}

SyntaxNode unwrap_parentheses(SyntaxNode node) {
  while (node && node.kind() == "parenthesized_expression" && node.named_child_count() == 1) node = node.named_child(0);
  return node;
}

}  // namespace

TimeUnit time_unit_of(const Type* type) {
  switch (type->kind) {
    case TypeKind::Duration:
    case TypeKind::TimeOfDay: return type->long_variant ? TimeUnit::Nanoseconds : TimeUnit::Milliseconds;
    case TypeKind::Date:
    case TypeKind::DateTime: return type->long_variant ? TimeUnit::Nanoseconds : TimeUnit::Seconds;
    default: return TimeUnit::Milliseconds;
  }
}

void Lowering::write_constant(std::vector<uint8_t>& bytes, uint64_t at, const Type* type,
                              const check::ConstValue& value) {
  type = Layouts::storage_type(type);
  if (!type) return;
  using Kind = check::ConstValue::Kind;
  if (type->kind == TypeKind::String || type->kind == TypeKind::WString) {
    const bool wide = type->kind == TypeKind::WString;
    std::string encoded = wide ? utf8_to_utf16le(value.text) : utf8_to_single_byte(value.text);
    const size_t unit = wide ? 2 : 1;
    const size_t capacity = static_cast<size_t>(type->length) * unit;
    if (encoded.size() > capacity) encoded.resize(capacity);
    encoded.append(unit, '\0');
    put(bytes, at, encoded.data(), encoded.size());
    return;
  }
  const Scalar scalar = Layouts::scalar_of(type);
  if (scalar == Scalar::F32) {
    const auto v = static_cast<float>(value.as_real());
    put(bytes, at, &v, 4);
    return;
  }
  if (scalar == Scalar::F64) {
    const double v = value.as_real();
    put(bytes, at, &v, 8);
    return;
  }
  __int128 number = value.kind == Kind::Real ? static_cast<__int128>(value.real) : value.integer;
  if (value.kind == Kind::Duration && type->kind == TypeKind::Duration && !type->long_variant) {
    number = value.integer / 1'000'000;  // TIME counts milliseconds
  }
  const TypeLayout layout = layouts_.of(type);
  put_integer(bytes, at, static_cast<uint64_t>(number), std::min<uint64_t>(layout.size, 8));
}

void Lowering::write_default(std::vector<uint8_t>& bytes, uint64_t at, const Type* type, int depth) {
  if (!type || depth > kMaxDepth) return;
  switch (type->kind) {
    case TypeKind::Alias:
      if (type->declaration) {
        SyntaxNode value = type->declaration->node.child_by_field("value");
        if (value) {
          write_initializer(bytes, at, type->element, value, type->declaration, depth + 1);
          return;
        }
      }
      write_default(bytes, at, type->element, depth + 1);
      return;
    case TypeKind::Subrange: {
      // IEC 61131-3: a subrange variable starts at its lower limit.
      check::ConstValue lower = check::ConstValue::of_integer(type->range_lower);
      if (type->range_lower > 0 || type->range_upper < 0) write_constant(bytes, at, type->element, lower);
      return;
    }
    case TypeKind::Enum: {
      const Symbol* declaration = type->declaration;
      if (!declaration) return;
      SyntaxNode node = declaration->node;
      if (node.kind() == "type_declaration" && node.named_child_count() > 0) node = node.named_child(0);
      SyntaxNode value = node.child_by_field("value");
      if (value) {
        if (auto constant = model_.constant_value(value, declaration)) write_constant(bytes, at, type, *constant);
        return;
      }
      for (const Symbol* member : declaration->ordered) {
        if (member->kind != SymbolKind::EnumValue) continue;
        if (auto number = model_.enum_value(member)) {
          write_constant(bytes, at, type, check::ConstValue::of_integer(*number));
        }
        return;
      }
      return;
    }
    case TypeKind::Struct: {
      if (!type->declaration) return;
      layouts_.of(type);
      if (type->declaration->base && type->declaration->base->type) {
        write_default(bytes, at, type->declaration->base->type, depth + 1);
      }
      for (const Symbol* field : type->declaration->ordered) {
        if (field->kind == SymbolKind::Variable) write_variable_initial(bytes, at + layouts_.offset(field), field);
      }
      return;
    }
    case TypeKind::Union: {
      if (!type->declaration) return;
      layouts_.of(type);
      for (const Symbol* field : type->declaration->ordered) {
        if (field->kind == SymbolKind::Variable && (field->flags & check::kHasInitializer)) {
          write_variable_initial(bytes, at, field);
          return;
        }
      }
      return;
    }
    case TypeKind::Array: {
      const TypeLayout whole = layouts_.of(type);
      const TypeLayout element = layouts_.of(type->element);
      if (element.size == 0 || whole.size == 0) return;
      std::vector<uint8_t> one(element.size, 0);
      write_default(one, 0, type->element, depth + 1);
      one.resize(element.size);
      bool zero = true;
      for (uint8_t b : one) zero = zero && b == 0;
      if (zero) return;
      if (at + whole.size > bytes.size()) bytes.resize(at + whole.size, 0);
      for (uint64_t offset = 0; offset + element.size <= whole.size; offset += element.size) {
        std::memcpy(bytes.data() + at + offset, one.data(), element.size);
      }
      return;
    }
    case TypeKind::Pou:
      if (type->declaration && type->declaration->kind != SymbolKind::Interface) {
        write_instance(bytes, at, type->declaration, depth + 1);
      }
      return;
    default: return;
  }
}

void Lowering::write_instance(std::vector<uint8_t>& bytes, uint64_t at, const Symbol* pou, int depth) {
  if (depth > kMaxDepth) return;
  const PouLayout& layout = layouts_.pou(pou);
  if (at + layout.instance_size > bytes.size()) bytes.resize(at + layout.instance_size, 0);
  if (Layouts::has_instance_header(pou)) put_integer(bytes, at, class_id(pou), 4);
  for (const Symbol* variable : layout.instance_variables) {
    write_variable_initial(bytes, at + layouts_.offset(variable), variable);
  }
}

namespace {

// Whether an initial value can only be computed when the program runs (ADR(x), a function call,
// another variable): not an initializer list, a literal or a constant expression.
bool needs_runtime(const check::ProjectModel& model, SyntaxNode value, const Symbol* scope) {
  value = unwrap_parentheses(value);
  const std::string_view kind = value.kind();
  if (kind == "array_initializer" || kind == "struct_initializer" || kind == "date_literal" ||
      kind == "time_of_day_literal" || kind == "date_and_time_literal") {
    return false;
  }
  return !model.constant_value(value, scope).has_value();
}

}  // namespace

bool Lowering::computed_initial(const Symbol* variable) const {
  SyntaxNode value = variable->node.child_by_field("value");
  const Symbol* owner = variable->owner;
  if (!value || !owner || variable->kind != SymbolKind::Variable) return false;
  if (variable->section == ast::VarSection::Stat || variable->section == ast::VarSection::External) return false;
  if (!needs_runtime(model_, value, owner)) return false;
  // Programs, global lists, FB instances (their constructor) and call frames compute such values
  // in code; a structure's field initialiser must stay a constant.
  switch (owner->kind) {
    case SymbolKind::Program:
    case SymbolKind::GlobalList:
    case SymbolKind::Function:
    case SymbolKind::Method:
    case SymbolKind::FunctionBlock:
    case SymbolKind::Class: return true;
    default: return variable->section == ast::VarSection::Temp;
  }
}

void Lowering::write_variable_initial(std::vector<uint8_t>& bytes, uint64_t at, const Symbol* variable) {
  const Type* type = variable->type;
  if (!type) return;
  SyntaxNode value = variable->node.child_by_field("value");
  if (computed_initial(variable)) return;  // computed in code (initialize_variables)
  if (Layouts::held_by_reference(variable)) return;
  if (!value) {
    write_default(bytes, at, type);
    return;
  }
  write_initializer(bytes, at, type, value, variable->owner ? variable->owner : variable, 0);
}

void Lowering::write_initializer(std::vector<uint8_t>& bytes, uint64_t at, const Type* type, SyntaxNode value,
                                 const Symbol* scope, int depth) {
  if (!type || !value || depth > kMaxDepth) return;
  value = unwrap_parentheses(value);
  const Type* storage = Layouts::storage_type(type);
  const std::string_view kind = value.kind();
  if (kind == "array_initializer" && storage->kind == TypeKind::Array) {
    write_default(bytes, at, type, depth + 1);
    const TypeLayout whole = layouts_.of(storage);
    const TypeLayout element = layouts_.of(storage->element);
    const Type* element_type = storage->element;
    // Multi-dimensional arrays take one flat list (CODESYS) or nested lists.
    uint64_t offset = 0;
    auto write_one = [&](SyntaxNode item) {
      if (offset + element.size > whole.size) return;
      write_initializer(bytes, at + offset, element_type, item, scope, depth + 1);
      offset += element.size;
    };
    for (uint32_t i = 0; i < value.named_child_count(); ++i) {
      SyntaxNode item = value.named_child(i);
      if (item.kind() == "comment" || item.kind() == "pragma") continue;
      if (item.kind() == "repeated_initializer") {
        const auto count = check::parse_integer_literal(item.child_by_field("count").text()).value_or(0);
        SyntaxNode repeated;
        for (uint32_t j = 0; j < item.named_child_count(); ++j) {
          if (item.named_child(j) != item.child_by_field("count")) repeated = item.named_child(j);
        }
        for (__int128 n = 0; n < count && offset < whole.size; ++n) {
          if (repeated) {
            write_one(repeated);
          } else {
            offset += element.size;  // 3() leaves the default
          }
        }
      } else if (item.kind() == "array_initializer" && Layouts::storage_type(element_type)->kind != TypeKind::Array &&
                 storage->dimensions.size() > 1) {
        for (uint32_t j = 0; j < item.named_child_count(); ++j) write_one(item.named_child(j));
      } else {
        write_one(item);
      }
    }
    return;
  }
  if (kind == "struct_initializer") {
    const Symbol* container = nullptr;
    if (storage->kind == TypeKind::Struct || storage->kind == TypeKind::Union || storage->kind == TypeKind::Pou) {
      container = storage->declaration;
    }
    if (!container) return;
    if (storage->kind == TypeKind::Pou) {
      write_instance(bytes, at, container, depth + 1);
    } else {
      write_default(bytes, at, type, depth + 1);
    }
    for (SyntaxNode field : value.children_of_kind("field_initializer")) {
      const Symbol* member = model_.find_member(container, field.child_by_field("name").text());
      if (!member || member->kind != SymbolKind::Variable) continue;
      write_initializer(bytes, at + layouts_.offset(member), member->type, field.child_by_field("value"), scope,
                        depth + 1);
    }
    return;
  }
  // Dates and times of day: literals the constant evaluator does not read.
  if (kind == "date_literal" || kind == "time_of_day_literal" || kind == "date_and_time_literal") {
    const PointKind point = kind == "date_literal"          ? PointKind::Date
                            : kind == "time_of_day_literal" ? PointKind::TimeOfDay
                                                            : PointKind::DateAndTime;
    if (auto number = parse_point_literal(value.text(), point, time_unit_of(storage))) {
      write_constant(bytes, at, type, check::ConstValue::of_integer(*number));
    }
    return;
  }
  if (auto constant = model_.constant_value(value, scope)) {
    write_constant(bytes, at, type, *constant);
    return;
  }
  error(scope, value,
        "this initial value is not a constant: rung runs only constant initial values so far (assign it in the "
        "body instead)");
}

}  // namespace rung::run
