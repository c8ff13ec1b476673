#include "checker/semantic/configuration_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <unordered_map>
#include <utility>

#include "checker/semantic/address_checker.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::check {
namespace {

// Deeper FB nesting than this is a cycle in broken code, not a real instance tree.
constexpr size_t kMaxInstanceDepth = 24;
// EXTENDS chains are followed this far: a cycle (E211) must not hang the walk.
constexpr int kMaxBaseDepth = 40;
// An incomplete address missing in many instances is named for the first few of them.
constexpr size_t kPathsNamed = 3;

std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& candidates) {
  const std::string_view near = closest_name(name, candidates);
  return near.empty() ? std::string() : fmt::format("did you mean '{}'?", near);
}

// A PROGRAM instance of a configuration: `PROGRAM Inst1 WITH Fast : Main;`.
struct ProgramInstance {
  SyntaxNode node;            // program_configuration
  SyntaxNode configuration;   // configuration_declaration
  std::string_view resource;  // empty at configuration level
  std::string_view name;
  const Symbol* program = nullptr;  // the PROGRAM it instantiates; nullptr if unknown
};

const Symbol* program_named(const ProjectModel& model, std::string_view name) {
  const Symbol* found = model.find_global(name);
  return found && found->kind == SymbolKind::Program ? found : nullptr;
}

void add_instances(const ProjectModel& model, SyntaxNode holder, SyntaxNode configuration, std::string_view resource,
                   std::vector<ProgramInstance>& out) {
  for (SyntaxNode node : holder.children_of_kind("program_configuration")) {
    ProgramInstance instance{node, configuration, resource, node.child_by_field("name").text()};
    if (SyntaxNode type = node.child_by_field("type")) instance.program = program_named(model, type.text());
    out.push_back(instance);
  }
}

// The configurations of the project: their resources and the program instances they run.
struct ConfigurationIndex {
  struct Resource {
    SyntaxNode configuration;
    std::string_view name;
  };
  std::vector<Resource> resources;
  std::vector<ProgramInstance> instances;
};

ConfigurationIndex index_configurations(const ProjectModel& model) {
  ConfigurationIndex index;
  for (SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library) continue;
    for (const Symbol* symbol : model.source(id).symbols.top_level) {
      if (symbol->kind != SymbolKind::Configuration) continue;
      add_instances(model, symbol->node, symbol->node, {}, index.instances);
      for (SyntaxNode resource : symbol->node.children_of_kind("resource_declaration")) {
        const std::string_view name = resource.child_by_field("name").text();
        index.resources.push_back({symbol->node, name});
        add_instances(model, resource, symbol->node, name, index.instances);
      }
    }
  }
  return index;
}

bool same_node(SyntaxNode a, SyntaxNode b) {
  return a == b;
}

std::string pointer_key(char kind, const void* pointer) {
  return fmt::format("{}{}", kind, pointer);
}

// What a type's values have as members: a POU instance's or a structure's declaration.
const Symbol* members_of(const Type* type) {
  const Type* base = underlying(type);
  if (!base || !base->declaration) return nullptr;
  if (base->kind == TypeKind::Pou || base->kind == TypeKind::Struct || base->kind == TypeKind::Union) {
    return base->declaration;
  }
  return nullptr;
}

// The instance trees VAR_CONFIG paths walk: sections whose variables live in the instance.
bool lives_in_instance(const Symbol& variable) {
  switch (variable.section) {
    case ast::VarSection::External:
    case ast::VarSection::InOut:
    case ast::VarSection::Temp:
    case ast::VarSection::Global:
    case ast::VarSection::Config:
    case ast::VarSection::Access: return false;
    default: return true;
  }
}

// A VAR_CONFIG entry's path (`Cpu.Inst1.fbSensor.bInput`) followed to the variable it names.
struct ResolvedPath {
  const Symbol* target = nullptr;
  // Which instance tree the path walks: a configuration's program instance, a PROGRAM called by
  // its name (CODESYS), or a global variable; with the variables from there down to the target.
  std::string root;
  std::vector<const Symbol*> chain;
  // When the path does not resolve: the segment at fault and what is wrong with it. An empty
  // problem with no target means the path cannot be judged (an unknown program type: E506).
  SyntaxNode bad_segment;
  std::string problem;
  std::string help;
};

class PathResolver {
 public:
  PathResolver(const ProjectModel& model, const ConfigurationIndex& index)
      : model_(model), index_(index), instances_(index.instances) {}

  ResolvedPath resolve(const Symbol& entry) const {
    ResolvedPath result;
    const std::vector<SyntaxNode> segments = segments_of(entry);
    if (segments.empty()) return result;
    SyntaxNode configuration = enclosing(entry.node, "configuration_declaration");
    size_t next = 0;
    const Symbol* container = nullptr;  // whose members the next segment names
    const Symbol* variable = nullptr;   // the variable the path has reached
    if (!start(segments, configuration, result, next, container, variable)) return result;
    for (; next < segments.size(); ++next) {
      const std::string_view name = segments[next].text();
      if (variable) {
        container = members_of(model_.type_of(variable));
        if (!container) {
          fail(result, segments[next],
               fmt::format("'{}' is {}, which has no member '{}'", variable->name, model_.type_of(variable)->name,
                           name));
          return result;
        }
      }
      const Symbol* member = model_.find_member(container, name);
      if (!member || member->kind != SymbolKind::Variable) {
        fail(result, segments[next], fmt::format("'{}' has no variable '{}'", container->name, name),
             did_you_mean(name, variable_names(container)));
        return result;
      }
      variable = member;
      result.chain.push_back(member);
    }
    if (!variable) {
      fail(result, segments.back(), fmt::format("'{}' is a program instance, not a variable", entry.name),
           "name a variable of the instance: <instance>.<variable>");
      return result;
    }
    result.target = variable;
    return result;
  }

 private:
  static std::vector<SyntaxNode> segments_of(const Symbol& entry) {
    for (SyntaxNode name : entry.node.children_by_field("name")) {
      if (name.range().begin != entry.name_range.begin) continue;
      if (name.kind() != "qualified_name") return {name};
      std::vector<SyntaxNode> segments;
      for (uint32_t i = 0; i < name.named_child_count(); ++i) {
        if (name.named_child(i).kind() == "identifier") segments.push_back(name.named_child(i));
      }
      return segments;
    }
    return {};
  }

  static SyntaxNode enclosing(SyntaxNode node, std::string_view kind) {
    for (SyntaxNode walk = node; walk; walk = walk.parent()) {
      if (walk.kind() == kind) return walk;
    }
    return SyntaxNode();
  }

  static void fail(ResolvedPath& result, SyntaxNode segment, std::string problem, std::string help = {}) {
    result.bad_segment = segment;
    result.problem = std::move(problem);
    result.help = std::move(help);
  }

  std::vector<std::string_view> variable_names(const Symbol* container) const {
    std::vector<std::string_view> names;
    int depth = 0;
    for (const Symbol* walk = container; walk && depth < kMaxBaseDepth; walk = walk->base, ++depth) {
      for (const Symbol* member : walk->ordered) {
        if (member->kind == SymbolKind::Variable) names.push_back(member->name);
      }
    }
    return names;
  }

  // The instance named `name` in `resource` (empty: at configuration level) of `configuration`
  // (null: of any configuration).
  const ProgramInstance* instance(SyntaxNode configuration, std::string_view resource, std::string_view name) const {
    for (const ProgramInstance& candidate : instances_) {
      if (configuration && !same_node(candidate.configuration, configuration)) continue;
      if (names_equal(candidate.resource, resource) && names_equal(candidate.name, name)) return &candidate;
    }
    return nullptr;
  }

  bool is_resource(SyntaxNode configuration, std::string_view name) const {
    for (const ConfigurationIndex::Resource& resource : index_.resources) {
      if (configuration && !same_node(resource.configuration, configuration)) continue;
      if (names_equal(resource.name, name)) return true;
    }
    return false;
  }

  bool start_at_instance(const ProgramInstance& found, ResolvedPath& result, const Symbol*& container) const {
    if (!found.program) return false;  // unknown program type: E506 at the PROGRAM line
    result.root = pointer_key('I', found.node.identity());
    container = found.program;
    return true;
  }

  // A path that starts at a global variable (it takes `used` segments to name it).
  static bool start_at_global(const Symbol* member, size_t used, ResolvedPath& result, size_t& next,
                              const Symbol*& variable) {
    result.root = "G";
    result.chain.push_back(member);
    variable = member;
    next = used;
    return true;
  }

  // Reads the first segments: the root of the instance tree. False when the path ends there.
  bool start(const std::vector<SyntaxNode>& segments, SyntaxNode configuration, ResolvedPath& result, size_t& next,
             const Symbol*& container, const Symbol*& variable) const {
    const std::string_view first = segments[0].text();
    // IEC 61131-3: resource.instance.variable, or instance.variable at configuration level.
    if (is_resource(configuration, first)) {
      if (segments.size() < 2) {
        fail(result, segments[0], fmt::format("'{}' is a resource, not a variable", first));
        return false;
      }
      if (const ProgramInstance* found = instance(configuration, first, segments[1].text())) {
        next = 2;
        return start_at_instance(*found, result, container);
      }
      if (const Symbol* member = model_.find_global_variable(segments[1].text())) {  // the resource's VAR_GLOBAL
        return start_at_global(member, 2, result, next, variable);
      }
      std::vector<std::string_view> names;
      for (const ProgramInstance& candidate : instances_) {
        if (names_equal(candidate.resource, first)) names.push_back(candidate.name);
      }
      fail(result, segments[1], fmt::format("resource '{}' runs no program instance '{}'", first, segments[1].text()),
           did_you_mean(segments[1].text(), names));
      return false;
    }
    if (const ProgramInstance* found = instance(configuration, {}, first)) {
      next = 1;
      return start_at_instance(*found, result, container);
    }
    // CODESYS: the PROGRAM by its name (MP300 manual L11660: PLC_PRG.locioVar1.xLocIn).
    if (const Symbol* program = program_named(model_, first)) {
      result.root = pointer_key('P', program);
      container = program;
      next = 1;
      return true;
    }
    // A global instance: GVL.instance.variable or instance.variable.
    const Symbol* global = model_.find_global(first);
    if (global && global->kind == SymbolKind::GlobalList && segments.size() > 1) {
      if (const Symbol* member = global->own_member(segments[1].text())) {
        return start_at_global(member, 2, result, next, variable);
      }
    }
    if (const Symbol* member = model_.find_global_variable(first)) {
      return start_at_global(member, 1, result, next, variable);
    }
    std::vector<std::string_view> names;
    for (const ProgramInstance& candidate : instances_)
      names.push_back(candidate.resource.empty() ? candidate.name : candidate.resource);
    fail(result, segments[0],
         fmt::format("'{}' is not a resource, program instance, PROGRAM or global variable", first),
         did_you_mean(first, names));
    return false;
  }

  const ProjectModel& model_;
  const ConfigurationIndex& index_;
  const std::vector<ProgramInstance>& instances_;
};

std::string chain_key(const std::string& root, const std::vector<const Symbol*>& chain) {
  std::string key = root;
  for (const Symbol* variable : chain) key += pointer_key('.', variable);
  return key;
}

// Walks every instance tree of the project to find the incomplete addresses VAR_CONFIG misses.
class CoverageWalker {
 public:
  CoverageWalker(const ProjectModel& model, const std::set<std::string>& configured, ConfigurationTable& table)
      : model_(model), configured_(configured), table_(table) {}

  // `alternative` is a second root key whose entries count too (a PROGRAM named directly for
  // one of its configuration instances).
  void walk(const Symbol* container, const std::string& root, const std::string& alternative,
            std::vector<const Symbol*>& chain, const std::string& path) {
    // An FB that contains itself (E209) would otherwise expand without end.
    if (chain.size() > kMaxInstanceDepth || std::find(open_.begin(), open_.end(), container) != open_.end()) return;
    open_.push_back(container);
    int depth = 0;
    for (const Symbol* walk = container; walk && depth < kMaxBaseDepth; walk = walk->base, ++depth) {
      for (const Symbol* variable : walk->ordered) {
        if (variable->kind != SymbolKind::Variable || !lives_in_instance(*variable)) continue;
        chain.push_back(variable);
        const std::string here = path + "." + std::string(variable->name);
        visit(*variable, root, alternative, chain, here);
        chain.pop_back();
      }
    }
    open_.pop_back();
  }

  void visit(const Symbol& variable, const std::string& root, const std::string& alternative,
             std::vector<const Symbol*>& chain, const std::string& path) {
    std::optional<DirectAddress> address = declared_address(model_, variable);
    if (address && address->wildcard && !configured_.count(chain_key(root, chain)) &&
        (alternative.empty() || !configured_.count(chain_key(alternative, chain)))) {
      table_.unconfigured[&variable].push_back(path);
    }
    const Symbol* block = members_of(model_.type_of(&variable));
    if (block && block->kind == SymbolKind::FunctionBlock && has_incomplete(block)) {
      walk(block, root, alternative, chain, path);
    }
  }

 private:
  // Whether an FB's instances contain an incomplete address at all: most do not, and the walk
  // skips them instead of expanding every instance of the project.
  bool has_incomplete(const Symbol* block) {
    auto [it, inserted] = memo_.emplace(block, false);  // false while in progress: cycles end here
    if (!inserted) return it->second;
    bool found = false;
    int depth = 0;
    for (const Symbol* walk = block; walk && !found && depth < kMaxBaseDepth; walk = walk->base, ++depth) {
      for (const Symbol* variable : walk->ordered) {
        if (variable->kind != SymbolKind::Variable || !lives_in_instance(*variable)) continue;
        std::optional<DirectAddress> address = declared_address(model_, *variable);
        const Symbol* inner = members_of(model_.type_of(variable));
        if ((address && address->wildcard) ||
            (inner && inner->kind == SymbolKind::FunctionBlock && inner != block && has_incomplete(inner))) {
          found = true;
          break;
        }
      }
    }
    memo_[block] = found;
    return found;
  }

  const ProjectModel& model_;
  const std::set<std::string>& configured_;
  ConfigurationTable& table_;
  std::unordered_map<const Symbol*, bool> memo_;
  std::vector<const Symbol*> open_;  // the FBs being walked, outermost first
};

// The VAR_CONFIG entries of one file. VAR_CONFIG inside a POU is E201 already: its entries
// would only add follow-up errors.
void add_config_entries(const Source& source, std::vector<const Symbol*>& entries) {
  if (source.library) return;
  for (const Symbol& symbol : source.symbols.storage) {
    if (symbol.kind == SymbolKind::Variable && symbol.section == ast::VarSection::Config && symbol.owner &&
        symbol.owner->kind == SymbolKind::GlobalList) {
      entries.push_back(&symbol);
    }
  }
}

std::string_view area_name(AddressArea area) {
  switch (area) {
    case AddressArea::Input: return "an input";
    case AddressArea::Output: return "an output";
    case AddressArea::Memory: return "a memory";
  }
  return "an";
}

class ConfigurationChecker {
 public:
  ConfigurationChecker(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out)
      : model_(model), source_(source), out_(out) {}

  void run() {
    for (const Symbol* symbol : model_.source(source_).symbols.top_level) {
      if (symbol->kind == SymbolKind::Configuration) check_configuration(*symbol);
    }
    std::vector<const Symbol*> entries;
    add_config_entries(model_.source(source_), entries);
    if (!entries.empty()) {
      const ConfigurationIndex index = index_configurations(model_);
      const PathResolver resolver(model_, index);
      for (const Symbol* entry : entries) check_entry(*entry, resolver.resolve(*entry));
    }
    report_unconfigured();
  }

 private:
  void report(std::string_view code, std::string message, TextRange range, std::string help = {}) {
    out_.push_back(make_diagnostic(code, std::move(message), range, std::move(help)));
  }

  // --- CONFIGURATION / RESOURCE / TASK / PROGRAM ----------------------------------------------

  void check_configuration(const Symbol& configuration) {
    const std::vector<SyntaxNode> own_tasks = configuration.node.children_of_kind("task_configuration");
    check_holder(configuration, configuration.node, own_tasks, {});
    for (SyntaxNode resource : configuration.node.children_of_kind("resource_declaration")) {
      check_holder(configuration, resource, own_tasks, resource.child_by_field("name").text());
    }
  }

  // A configuration or a resource: its tasks and the program instances they run. Programs of a
  // resource may use its own tasks and those of the configuration.
  void check_holder(const Symbol& configuration, SyntaxNode holder, const std::vector<SyntaxNode>& outer_tasks,
                    std::string_view resource) {
    std::vector<SyntaxNode> tasks = holder.children_of_kind("task_configuration");
    for (SyntaxNode task : tasks) check_task(configuration, task);
    if (holder.kind() == "resource_declaration") tasks.insert(tasks.end(), outer_tasks.begin(), outer_tasks.end());
    std::vector<std::string_view> task_names;
    task_names.reserve(tasks.size());
    for (SyntaxNode task : tasks) task_names.push_back(task.child_by_field("name").text());
    const std::string where = resource.empty() ? fmt::format("configuration '{}'", configuration.name)
                                               : fmt::format("resource '{}'", resource);
    for (SyntaxNode program : holder.children_of_kind("program_configuration")) {
      check_task_name(program.child_by_field("task"), task_names, where);
      check_program_type(program.child_by_field("type"));
      if (SyntaxNode arguments = program.child_by_field("arguments")) {
        for (SyntaxNode association : arguments.children_of_kind("task_association")) {
          check_task_name(association.child_by_field("task"), task_names, where);
        }
      }
    }
  }

  void check_task_name(SyntaxNode task, const std::vector<std::string_view>& declared, const std::string& where) {
    if (!task) return;
    for (std::string_view name : declared) {
      if (names_equal(name, task.text())) return;
    }
    report(codes::kUnknownProgramOrTask, fmt::format("task '{}' is not declared in {}", task.text(), where),
           task.range(), did_you_mean(task.text(), declared));
  }

  void check_program_type(SyntaxNode type) {
    if (!type) return;
    const Symbol* found = model_.find_global(type.text());
    if (found && found->kind == SymbolKind::Program) return;
    if (found) {
      report(codes::kUnknownProgramOrTask,
             fmt::format("'{}' is a {}, not a PROGRAM: a resource runs programs", type.text(),
                         symbol_kind_name(found->kind)),
             type.range());
      return;
    }
    std::vector<std::string_view> programs;
    for (SourceId id = 0; id < model_.source_count(); ++id) {
      for (const Symbol* symbol : model_.source(id).symbols.top_level) {
        if (symbol->kind == SymbolKind::Program && !symbol->name.empty()) programs.push_back(symbol->name);
      }
    }
    report(codes::kUnknownProgramOrTask, fmt::format("there is no PROGRAM '{}' in the project", type.text()),
           type.range(), did_you_mean(type.text(), programs));
  }

  void check_task(const Symbol& configuration, SyntaxNode task) {
    const SyntaxNode name = task.child_by_field("name");
    bool triggered = false;
    if (SyntaxNode arguments = task.child_by_field("arguments")) {
      for (SyntaxNode argument : arguments.children_of_kind("argument")) {
        const SyntaxNode parameter = argument.child_by_field("name");
        if (!parameter) continue;
        const std::string_view text = parameter.text();
        if (names_equal(text, "INTERVAL") || names_equal(text, "SINGLE")) {
          triggered = true;
        } else if (names_equal(text, "PRIORITY")) {
          check_priority(configuration, argument.child_by_field("value"));
        } else {
          static const std::vector<std::string_view> kParameters{"INTERVAL", "SINGLE", "PRIORITY"};
          report(codes::kUnknownParameter,
                 fmt::format("a TASK has no parameter '{}': it takes INTERVAL, SINGLE and PRIORITY", text),
                 parameter.range(), did_you_mean(text, kParameters));
        }
      }
    }
    if (!triggered && !model_.profile().freewheeling_tasks) {
      report(codes::kTaskWithoutTrigger,
             fmt::format("TASK '{}' has neither INTERVAL nor SINGLE, so it never runs", name ? name.text() : ""),
             name ? name.range() : task.range(),
             "give it INTERVAL := T#10MS to run cyclically, or SINGLE := <BOOL variable> to run on its rising edge");
    }
  }

  // CODESYS: priorities 0 (highest) to 31 (textbook L1568-1574, AK800 L2980-2984, MP300 L8559).
  void check_priority(const Symbol& configuration, SyntaxNode value) {
    const uint32_t highest = model_.profile().max_task_priority;
    if (!value || highest == 0) return;
    const std::optional<ConstValue> constant = model_.constant_value(value, &configuration);
    if (!constant || !constant->is_integer()) return;
    if (constant->integer < 0 || constant->integer > static_cast<__int128>(highest)) {
      report(codes::kLiteralOutOfRange,
             fmt::format("PRIORITY {} is out of range: task priorities are 0 (highest) to {}",
                         int128_to_string(constant->integer), highest),
             value.range());
    }
  }

  // --- VAR_CONFIG -----------------------------------------------------------------------------

  void check_entry(const Symbol& entry, const ResolvedPath& path) {
    if (!path.target) {
      if (!path.problem.empty()) {
        report(codes::kVarConfigPath, fmt::format("VAR_CONFIG path '{}': {}", entry.name, path.problem),
               path.bad_segment.range(), path.help);
      }
      return;
    }
    const Symbol& target = *path.target;
    const std::string owner = target.owner ? fmt::format(" in '{}'", target.owner->name) : std::string();
    const Type* wanted = model_.type_of(&target);
    const Type* given = model_.type_of(&entry);
    if (!wanted->is_unknown() && !given->is_unknown() && underlying(wanted) != underlying(given) &&
        !names_equal(wanted->name, given->name)) {
      report(codes::kVarConfigPath,
             fmt::format("'{}' is {}{}, but this VAR_CONFIG entry declares it {}", entry.name, wanted->name, owner,
                         given->name),
             entry.type_node ? entry.type_node.range() : entry.name_range,
             fmt::format("declare the entry as {}", wanted->name));
    }
    if (!entry.location_node) return;  // an entry may give only an initial value (IEC 61131-3)
    const std::optional<DirectAddress> address = declared_address(model_, entry);
    if (!address || address->wildcard) return;  // E505 from the address checks
    const TextRange range = entry.location_node.range();
    const std::optional<DirectAddress> declared = declared_address(model_, target);
    if (!target.location_node) {
      report(
          codes::kVarConfigPath,
          fmt::format("'{}'{} has no incomplete address (AT %I* or %Q*) for VAR_CONFIG to complete", entry.name, owner),
          range,
          fmt::format("declare '{}' AT %{}* where it is declared, or give this entry no address", target.name,
                      address->area == AddressArea::Input ? 'I' : 'Q'));
      return;
    }
    if (!declared) return;  // malformed: E505 at the declaration
    if (!declared->wildcard) {
      report(codes::kVarConfigPath,
             fmt::format("'{}' already has the address {}{}: VAR_CONFIG only completes incomplete addresses (%I*, %Q*)",
                         entry.name, format_direct_address(*declared), owner),
             range);
      return;
    }
    if (declared->area != address->area) {
      report(codes::kVarConfigPath,
             fmt::format("'{}' is declared AT {} ({} address) but gets {}, {} address", entry.name,
                         format_direct_address(*declared), area_name(declared->area), format_direct_address(*address),
                         area_name(address->area)),
             range);
    } else if (declared->size != AddressSize::None && declared->size_bits() != address->size_bits()) {
      report(codes::kVarConfigPath,
             fmt::format("'{}' is declared AT {} but gets {}, an address of another size", entry.name,
                         format_direct_address(*declared), format_direct_address(*address)),
             range);
    }
  }

  void report_unconfigured() {
    const ConfigurationTable& table = model_.configuration_table();
    for (const Symbol& symbol : model_.source(source_).symbols.storage) {
      auto found = table.unconfigured.find(&symbol);
      if (found == table.unconfigured.end() || found->second.empty()) continue;
      const std::vector<std::string>& paths = found->second;
      std::string named;
      for (size_t i = 0; i < paths.size() && i < kPathsNamed; ++i)
        named += fmt::format("{}'{}'", i ? ", " : "", paths[i]);
      if (paths.size() > kPathsNamed) named += fmt::format(" and {} more", paths.size() - kPathsNamed);
      const std::optional<DirectAddress> address = declared_address(model_, symbol);
      const SyntaxNode node = symbol.location_node;
      report(
          codes::kVarConfigPath,
          fmt::format("the incomplete address of '{}' is completed by no VAR_CONFIG entry for {}", symbol.name, named),
          node ? node.range() : symbol.name_range,
          fmt::format("add '{} AT %{}X… : {};' to a VAR_CONFIG", paths.front(),
                      address && address->area == AddressArea::Output ? 'Q' : 'I', model_.type_of(&symbol)->name));
    }
  }

  const ProjectModel& model_;
  SourceId source_;
  std::vector<Diagnostic>& out_;
};

}  // namespace

ConfigurationTable build_configuration_table(const ProjectModel& model) {
  ConfigurationTable table;
  std::vector<const Symbol*> entries;
  for (SourceId id = 0; id < model.source_count(); ++id) add_config_entries(model.source(id), entries);
  // Without any VAR_CONFIG the project completes its %I*/%Q* elsewhere (the I/O mapping dialog
  // of CODESYS), which rung cannot see: nothing to hold against it.
  if (entries.empty()) return table;
  const ConfigurationIndex index = index_configurations(model);
  const std::vector<ProgramInstance>& instances = index.instances;
  const PathResolver resolver(model, index);
  std::set<std::string> configured;
  for (const Symbol* entry : entries) {
    ResolvedPath path = resolver.resolve(*entry);
    if (path.target && entry->location_node) configured.insert(chain_key(path.root, path.chain));
  }
  CoverageWalker walker(model, configured, table);
  std::vector<const Symbol*> chain;
  if (!instances.empty()) {
    for (const ProgramInstance& instance : instances) {
      if (!instance.program) continue;
      const std::string path = instance.resource.empty() ? std::string(instance.name)
                                                         : fmt::format("{}.{}", instance.resource, instance.name);
      walker.walk(instance.program, pointer_key('I', instance.node.identity()), pointer_key('P', instance.program), chain,
                  path);
    }
  } else {
    for (SourceId id = 0; id < model.source_count(); ++id) {
      if (model.source(id).library) continue;
      for (const Symbol* symbol : model.source(id).symbols.top_level) {
        if (symbol->kind == SymbolKind::Program && !symbol->name.empty()) {
          walker.walk(symbol, pointer_key('P', symbol), {}, chain, std::string(symbol->name));
        }
      }
    }
  }
  for (SourceId id = 0; id < model.source_count(); ++id) {
    if (model.source(id).library) continue;
    for (const Symbol* list : model.source(id).symbols.global_lists) {
      for (const Symbol* variable : list->ordered) {
        if (variable->kind != SymbolKind::Variable || variable->section == ast::VarSection::Config) continue;
        chain.assign(1, variable);
        walker.visit(*variable, "G", {}, chain, std::string(variable->name));
      }
    }
  }
  return table;
}

void check_configurations(const ProjectModel& model, SourceId source, std::vector<Diagnostic>& out) {
  ConfigurationChecker(model, source, out).run();
}

}  // namespace rung::check
