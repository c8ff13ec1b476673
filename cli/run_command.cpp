#include "cli/run_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "checker/check.hpp"
#include "checker/constant/const_value.hpp"
#include "checker/symbols/names.hpp"
#include "cli/diagnostic_printer.hpp"
#include "cli/project_loading.hpp"
#include "runner/engine.hpp"
#include "runner/inspect.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/vm/disassemble.hpp"

namespace rung::cli {
namespace {

std::optional<uint64_t> parse_duration_ns(std::string_view text) {
  std::string literal(text);
  if (literal.find('#') == std::string::npos) literal = "T#" + literal;
  auto ns = check::parse_duration_literal(literal);
  if (!ns || *ns < 0) return std::nullopt;
  return static_cast<uint64_t>(*ns);
}

std::string time_text(uint64_t ns) { return run::duration_text(static_cast<int64_t>(ns), run::TimeUnit::Nanoseconds, false); }

// The condition of --until: a BOOL variable, or VAR=VALUE compared by the value's text.
struct UntilCondition {
  std::string variable;
  std::optional<std::string> expected;
};

UntilCondition parse_until(std::string_view text) {
  UntilCondition condition;
  const size_t equals = text.find('=');
  if (equals == std::string_view::npos) {
    condition.variable = std::string(text);
  } else {
    condition.variable = std::string(text.substr(0, equals));
    condition.expected = std::string(text.substr(equals + 1));
  }
  return condition;
}

bool until_met(const run::CompiledProject& project, const run::Machine& machine, const run::ValueRef& ref,
               const UntilCondition& condition) {
  const std::string current = run::value_text(project, machine, ref);
  if (!condition.expected) return current == "TRUE";
  // Compare as text after normalising the expected value through the same type.
  std::string expected = *condition.expected;
  if (check::names_equal(current, expected)) return true;
  return false;
}

nlohmann::ordered_json variables_json(const run::CompiledProject& project, const run::Machine& machine,
                              const std::vector<run::VariableView>& variables) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  for (const run::VariableView& variable : variables) {
    object[variable.name] = run::value_json(project, machine, run::variable_ref(machine, variable));
  }
  return object;
}

nlohmann::ordered_json state_json(const run::Engine& engine) {
  const run::CompiledProject& project = engine.project();
  nlohmann::ordered_json programs = nlohmann::ordered_json::object();
  for (const run::ProgramInstance& program : project.programs) {
    programs[program.name] = variables_json(project, engine.machine(), program.variables);
  }
  nlohmann::ordered_json globals = nlohmann::ordered_json::object();
  for (const run::GlobalList& list : project.globals) {
    globals[list.name] = variables_json(project, engine.machine(), list.variables);
  }
  return nlohmann::ordered_json{{"cycles", engine.cycles()},
                        {"time", time_text(engine.now_ns())},
                        {"programs", std::move(programs)},
                        {"globals", std::move(globals)}};
}

std::string type_name(const check::Type* type) { return type ? type->name : "?"; }

void print_table(std::FILE* out, const run::CompiledProject& project, const run::Machine& machine, std::string_view title,
                 const std::vector<run::VariableView>& variables, const Style& style) {
  if (variables.empty()) return;
  size_t name_width = 4;
  size_t type_width = 4;
  for (const run::VariableView& variable : variables) {
    name_width = std::max(name_width, variable.name.size());
    type_width = std::max(type_width, type_name(variable.type).size());
  }
  fmt::print(out, "{}{}{}\n", style.bold(), title, style.reset());
  for (const run::VariableView& variable : variables) {
    const std::string value = run::value_text(project, machine, run::variable_ref(machine, variable));
    fmt::print(out, "  {:<{}}  {:<{}}  {}\n", variable.name, name_width, type_name(variable.type), type_width, value);
  }
}

std::string csv_cell(std::string text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

CLI::App* add_run_subcommand(CLI::App& app, RunCommandOptions& options, std::string& format_text,
                             std::string& profile_text) {
  CLI::App* run = app.add_subcommand(
      "run", "Run a project's programs for some cycles on a virtual clock and print their variables");
  run->add_option("paths", options.paths, "A file, a folder or a project (default: the current folder)");
  run->add_option("--program", options.program, "The PROGRAM to run (default: the project's only program, PLC_PRG or MAIN)");
  run->add_option("--config", options.configuration, "The CONFIGURATION whose tasks run (default: the first one)");
  run->add_option("--cycles", options.cycles, "Cycles to run (default: 1)");
  run->add_option("--until", options.until,
                  "Run until a BOOL variable is TRUE, or until VAR=VALUE holds (at most --max-cycles)");
  run->add_option("--for", options.for_time, "Run until the virtual clock reaches this time (e.g. T#5s)");
  run->add_option("--tick", options.tick, "Time per cycle (default: the task's interval, else T#10ms)");
  run->add_option("--set", options.set, "VAR=VALUE before the first cycle (repeatable)");
  run->add_option("--watch", options.watch, "Variables to print after every cycle (comma-separated)")->delimiter(',');
  run->add_option("--trace", options.trace, "Write one CSV row per cycle to this file");
  run->add_option("--max-cycles", options.max_cycles, "Bound of --until and --for (default: 1000000)");
  run->add_option("--loop-limit", options.loop_limit,
                  "Watchdog: backward jumps allowed in one program call (default: 100000000)");
  run->add_flag("--dump-ir", options.dump_ir, "Print the compiled instructions instead of running");
  run->add_option("--format", format_text, "Output format")->check(CLI::IsMember({"human", "json"}));
  run->add_option("--profile", profile_text, "Semantics profile, overrides rung.toml")
      ->check(CLI::IsMember({"codesys", "iec", "twincat", "openpcs"}));
  return run;
}

int run_run_command(const RunCommandOptions& options, std::FILE* out, std::FILE* err) {
  Style style{use_color(options.color, err)};
  Style out_style{use_color(options.color, out)};
  std::optional<LoadedProject> loaded = load_project({options.paths, options.profile, 0}, style, err);
  if (!loaded) return 2;
  const check::Workspace& workspace = *loaded->workspace;
  if (!workspace.load_errors.empty() || loaded->config.has_errors) return 2;

  // A program that does not check does not run.
  size_t errors = 0;
  for (const check::FileDiagnostics& file : workspace.check_all()) {
    const Document& document = *workspace.model().source(file.source).document;
    for (const Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity != Severity::Error) continue;
      ++errors;
      const std::string text = render_human(document, diagnostic, style);
      std::fwrite(text.data(), 1, text.size(), err);
    }
  }
  if (errors > 0) {
    fmt::print(err, "{}error{}: the project has {} error{}; fix {} before running it (rung check shows them)\n",
               style.red(), style.reset(), errors, errors == 1 ? "" : "s", errors == 1 ? "it" : "them");
    return 2;
  }

  run::CompileOptions compile_options;
  compile_options.program = options.program;
  compile_options.configuration = options.configuration;
  const run::CompiledProject project = run::compile_project(workspace.model(), compile_options);
  if (!project.ok()) {
    for (const run::CompileError& error : project.errors) {
      if (error.source != check::kNoSource) {
        const Document& document = *workspace.model().source(error.source).document;
        const FilePosition position = document.position_of_tree_offset(error.offset);
        fmt::print(err, "{}error{}: {}:{}:{}: {}\n", style.red(), style.reset(), document.path(), position.line,
                   position.column, error.message);
      } else {
        fmt::print(err, "{}error{}: {}\n", style.red(), style.reset(), error.message);
      }
    }
    return 2;
  }

  if (options.dump_ir) {
    const std::string listing = run::disassemble(*project.program);
    std::fwrite(listing.data(), 1, listing.size(), out);
    keep_until_exit(std::move(loaded->workspace));
    return 0;
  }
  uint64_t tick = 0;
  if (!options.tick.empty()) {
    auto parsed = parse_duration_ns(options.tick);
    if (!parsed || *parsed == 0) {
      fmt::print(err, "error: --tick '{}' is not a positive duration (e.g. T#10ms)\n", options.tick);
      return 2;
    }
    tick = *parsed;
  }
  std::optional<uint64_t> for_ns;
  if (!options.for_time.empty()) {
    for_ns = parse_duration_ns(options.for_time);
    if (!for_ns) {
      fmt::print(err, "error: --for '{}' is not a duration (e.g. T#5s)\n", options.for_time);
      return 2;
    }
  }
  run::Engine engine(project, tick);
  engine.machine().set_loop_budget(options.loop_limit);

  for (const std::string& assignment : options.set) {
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos) {
      fmt::print(err, "error: --set '{}' needs VAR=VALUE\n", assignment);
      return 2;
    }
    std::string why;
    auto ref = run::resolve_path(project, engine.machine(), assignment.substr(0, equals), &why);
    if (!ref || !run::write_value(project, engine.machine(), *ref, assignment.substr(equals + 1), &why)) {
      fmt::print(err, "error: --set '{}': {}\n", assignment, why);
      return 2;
    }
  }
  std::vector<std::pair<std::string, run::ValueRef>> watched;
  for (const std::string& name : options.watch) {
    std::string why;
    auto ref = run::resolve_path(project, engine.machine(), name, &why);
    if (!ref) {
      fmt::print(err, "error: --watch: {}\n", why);
      return 2;
    }
    watched.emplace_back(name, *ref);
  }
  std::optional<UntilCondition> until;
  std::optional<run::ValueRef> until_ref;
  if (!options.until.empty()) {
    until = parse_until(options.until);
    std::string why;
    until_ref = run::resolve_path(project, engine.machine(), until->variable, &why);
    if (!until_ref) {
      fmt::print(err, "error: --until: {}\n", why);
      return 2;
    }
  }

  std::ofstream trace;
  std::vector<std::pair<std::string, run::ValueRef>> traced = watched;
  if (!options.trace.empty()) {
    trace.open(options.trace, std::ios::binary | std::ios::trunc);
    if (!trace) {
      fmt::print(err, "error: cannot write the trace file '{}'\n", options.trace);
      return 2;
    }
    if (traced.empty()) {
      for (const run::ProgramInstance& program : project.programs) {
        for (const run::VariableView& variable : program.variables) {
          traced.emplace_back(program.name + "." + variable.name, run::variable_ref(engine.machine(), variable));
        }
      }
    }
    trace << "cycle,time";
    for (const auto& [name, ref] : traced) trace << ',' << csv_cell(name);
    trace << '\n';
  }

  nlohmann::ordered_json watch_rows = nlohmann::ordered_json::array();
  const uint64_t bound = (until || for_ns) ? options.max_cycles : options.cycles.value_or(1);
  bool failed = false;
  for (uint64_t n = 0; n < bound; ++n) {
    if (for_ns && engine.now_ns() >= *for_ns) break;
    if (!engine.cycle()) {
      failed = true;
      break;
    }
    if (!watched.empty()) {
      if (options.format == RunFormat::Json) {
        nlohmann::ordered_json row{{"cycle", engine.cycles()}, {"time", time_text(engine.now_ns())}};
        for (const auto& [name, ref] : watched) row[name] = run::value_json(project, engine.machine(), ref);
        watch_rows.push_back(std::move(row));
      } else {
        std::string line = fmt::format("cycle {:>4}  {}", engine.cycles(), time_text(engine.now_ns()));
        for (const auto& [name, ref] : watched) {
          line += fmt::format("  {}={}", name, run::value_text(project, engine.machine(), ref));
        }
        fmt::print(out, "{}\n", line);
      }
    }
    if (trace.is_open()) {
      trace << engine.cycles() << ',' << csv_cell(time_text(engine.now_ns()));
      for (const auto& [name, ref] : traced) trace << ',' << csv_cell(run::value_text(project, engine.machine(), ref));
      trace << '\n';
    }
    if (until && until_met(project, engine.machine(), *until_ref, *until)) break;
  }

  const auto& error = engine.machine().error();
  if (options.format == RunFormat::Json) {
    nlohmann::ordered_json report = state_json(engine);
    if (!watch_rows.empty()) report["watch"] = std::move(watch_rows);
    if (error) report["error"] = run::describe_error(project, *error);
    fmt::print(out, "{}\n", report.dump(2));
  } else {
    fmt::print(out, "{}after {} cycle{}, {}{}\n", out_style.bold(), engine.cycles(), engine.cycles() == 1 ? "" : "s",
               time_text(engine.now_ns()), out_style.reset());
    for (const run::ProgramInstance& program : project.programs) {
      print_table(out, project, engine.machine(), "PROGRAM " + program.name, program.variables, out_style);
    }
    for (const run::GlobalList& list : project.globals) {
      print_table(out, project, engine.machine(), list.name, list.variables, out_style);
    }
  }
  // The run ends: FB_exit of the instances that declare it, after the report of the last cycle.
  if (!failed && !engine.finish()) failed = true;
  if (failed && engine.machine().error()) {
    fmt::print(err, "{}{}{}\n", style.red(), run::describe_error(project, *engine.machine().error()), style.reset());
    keep_until_exit(std::move(loaded->workspace));
    return 1;
  }
  keep_until_exit(std::move(loaded->workspace));
  return 0;
}

}  // namespace rung::cli
