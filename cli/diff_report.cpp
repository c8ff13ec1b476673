#include "cli/diff_report.hpp"

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include "cli/terminal.hpp"

namespace rung::cli {

using vcs::BodyChange;
using vcs::DeclarationChange;
using vcs::DiffReport;
using vcs::FileError;
using vcs::MemberChange;
using vcs::ObjectChange;

namespace {

std::string title(const ObjectChange& c) {
  std::string s = fmt::format("{} {} {}", c.change, c.kind, c.name);
  if (!c.old_name.empty()) s = fmt::format("{} {} {} (was {})", c.change, c.kind, c.name, c.old_name);
  if (!c.old_path.empty()) return s + fmt::format(" ({} -> {})", c.old_path, c.path);
  return s + fmt::format(" ({})", c.path);
}

std::string member_prefix(std::string_view member) {
  return member.empty() ? std::string() : fmt::format("{}: ", member);
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (const std::string& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

void append_indented_hunks(std::string& out, std::string_view diff, const Style& c) {
  size_t at = 0;
  while (at < diff.size()) {
    size_t end = diff.find('\n', at);
    end = end == std::string_view::npos ? diff.size() : end;
    const std::string_view line = diff.substr(at, end - at);
    std::string_view color;
    if (!line.empty() && line[0] == '+') color = c.green();
    if (!line.empty() && line[0] == '-') color = c.red();
    if (line.substr(0, 2) == "@@") color = c.cyan();
    out += fmt::format("    {}{}{}\n", color, line, color.empty() ? std::string_view() : c.reset());
    at = end + 1;
  }
}

}  // namespace

std::string render_human(const DiffReport& report, bool color) {
  const Style c{color};
  std::string out;
  for (const ObjectChange& change : report.changes) {
    out += fmt::format("{}{}{}\n", c.bold(), title(change), c.reset());
    for (const MemberChange& m : change.members) {
      const bool added = m.change == "added";
      out +=
          fmt::format("  {}{} {} {}{}\n", added ? c.green() : c.red(), added ? '+' : '-', m.kind, m.member, c.reset());
    }
    for (const DeclarationChange& d : change.declarations) {
      const std::string prefix = member_prefix(d.member);
      if (d.what.front() == "added") {
        out += fmt::format("  {}+ {}{}{}\n", c.green(), prefix, d.after, c.reset());
      } else if (d.what.front() == "removed") {
        out += fmt::format("  {}- {}{}{}\n", c.red(), prefix, d.before, c.reset());
      } else if (d.what.front() == "declaration") {
        out += fmt::format("  {}~ {}declaration{}\n", c.yellow(), prefix, c.reset());
        append_indented_hunks(out, d.diff, c);
      } else {
        out += fmt::format("  {}~ {}{}{} ({})\n", c.yellow(), prefix, d.name.empty() ? std::string() : d.name + ":",
                           c.reset(), join(d.what, ", "));
        out += fmt::format("    {}-{}{}\n", c.red(), d.before, c.reset());
        out += fmt::format("    {}+{}{}\n", c.green(), d.after, c.reset());
      }
    }
    for (const BodyChange& b : change.bodies) {
      out += fmt::format("  {}~ body of {}{}{}\n", c.yellow(), change.name, b.member.empty() ? "" : "." + b.member,
                         c.reset());
      append_indented_hunks(out, b.diff, c);
    }
  }
  for (const FileError& e : report.notes) out += fmt::format("note: {}: {}\n", e.path, e.message);
  return out;
}

std::string render_stat(const DiffReport& report, bool color) {
  const Style c{color};
  std::string out;
  std::map<std::string, size_t> counts;
  for (const ObjectChange& change : report.changes) {
    ++counts[change.change];
    size_t added = 0;
    size_t removed = 0;
    for (const BodyChange& b : change.bodies) {
      added += b.added_lines;
      removed += b.removed_lines;
    }
    std::string detail;
    if (!change.members.empty())
      detail += fmt::format(", {} member{}", change.members.size(), change.members.size() == 1 ? "" : "s");
    if (!change.declarations.empty()) {
      detail +=
          fmt::format(", {} declaration{}", change.declarations.size(), change.declarations.size() == 1 ? "" : "s");
    }
    if (!change.bodies.empty()) {
      detail +=
          fmt::format(", {} bod{} ({}+{}{} {}-{}{})", change.bodies.size(), change.bodies.size() == 1 ? "y" : "ies",
                      c.green(), added, c.reset(), c.red(), removed, c.reset());
    }
    out += fmt::format(" {:<9} {} {} | {}{}\n", change.change, change.kind, change.name, change.path, detail);
  }
  std::string summary;
  for (const auto& [what, n] : counts) summary += fmt::format("{}{} {}", summary.empty() ? "" : ", ", n, what);
  out += fmt::format(" {} object{} changed{}{}\n", report.changes.size(), report.changes.size() == 1 ? "" : "s",
                     summary.empty() ? "" : ": ", summary);
  return out;
}

std::string render_json(const DiffReport& report) {
  nlohmann::ordered_json changes = nlohmann::ordered_json::array();
  for (const ObjectChange& change : report.changes) {
    nlohmann::ordered_json j;
    j["change"] = change.change;
    j["kind"] = change.kind;
    j["name"] = change.name;
    j["path"] = change.path;
    if (!change.old_name.empty()) j["old_name"] = change.old_name;
    if (!change.old_path.empty()) j["old_path"] = change.old_path;
    nlohmann::ordered_json members = nlohmann::ordered_json::array();
    for (const MemberChange& m : change.members) {
      members.push_back({{"change", m.change}, {"kind", m.kind}, {"member", m.member}});
    }
    nlohmann::ordered_json declarations = nlohmann::ordered_json::array();
    for (const DeclarationChange& d : change.declarations) {
      nlohmann::ordered_json dj;
      dj["member"] = d.member;
      dj["name"] = d.name;
      dj["what"] = d.what;
      if (!d.before.empty()) dj["before"] = d.before;
      if (!d.after.empty()) dj["after"] = d.after;
      if (!d.diff.empty()) dj["diff"] = d.diff;
      declarations.push_back(std::move(dj));
    }
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const BodyChange& b : change.bodies) {
      bodies.push_back({{"member", b.member},
                        {"kind", b.kind},
                        {"added_lines", b.added_lines},
                        {"removed_lines", b.removed_lines},
                        {"diff", b.diff}});
    }
    j["members"] = std::move(members);
    j["declarations"] = std::move(declarations);
    j["bodies"] = std::move(bodies);
    changes.push_back(std::move(j));
  }
  const auto file_messages = [](const std::vector<FileError>& list) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const FileError& e : list) out.push_back({{"path", e.path}, {"message", e.message}});
    return out;
  };
  nlohmann::ordered_json root;
  root["files"] = report.files;
  root["changes"] = std::move(changes);
  root["errors"] = file_messages(report.errors);
  root["notes"] = file_messages(report.notes);
  return root.dump(2) + "\n";
}

}  // namespace rung::cli
