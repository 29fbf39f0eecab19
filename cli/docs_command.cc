// arbc docs SPEC|APP.json [-o DIR]: index.md, app.dot, app.svg, app.mmd (docs/cli.md#arbc-docs).
// Above docs::kMaxDiagramElements only index.md: the drawings are skipped, and it says so.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/commands.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "compiler/docs/graph_docs.h"
#include "compiler/docs/markdown_docs.h"
#include "harness/model_loader.h"
#include "verify/report_format.h"
#include "verify/verify.h"

namespace arbc::cli {

namespace {

bool write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

// The verifier's text report of `app` (as `arbc verify` prints it, without timings); `input` is
// the file as the user named it.
std::string verification_text(const model::App& app, const std::string& input) {
  std::string error;
  std::optional<verify::VerifyReport> report =
      verify::verify_app(app, verify::VerifyOptions{}, &error);
  if (!report) return "not verified: " + error + "\n";
  std::vector<verify::InputReport> inputs;
  inputs.emplace_back(input, std::move(*report));
  std::string text = verify::format_text(inputs, nullptr, /*stats=*/false);
  // The page is an artifact for other machines: no path of this one. The report names the spec
  // as given (and its lines as file:line); a spec given by an absolute path is named by its
  // file name alone.
  std::filesystem::path given(input);
  if (!given.is_absolute()) return text;
  const std::string folder = given.parent_path().string() + "/";
  for (size_t at = text.find(folder); at != std::string::npos; at = text.find(folder, at))
    text.erase(at, folder.size());
  return text;
}

}  // namespace

int docs_command(std::span<char*> args) {
  CLI::App cli{"Write Markdown, Graphviz (DOT and SVG) and Mermaid documentation of an app.",
               "arbc docs"};
  std::string input;
  std::string out_dir = "docs-out";
  cli.add_option("SPEC", input, "the spec (or a built app.json, or its directory)")->required();
  std::vector<std::string> msg_path;
  add_msg_path_option(cli, &msg_path);
  cli.add_option("-o,--output", out_dir, "directory to write into (default: docs-out)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }

  harness::LoadNotes notes;
  std::string load_error;
  std::optional<model::App> app = harness::load_model(input, &notes, &load_error);
  if (!notes.rendered.empty()) std::fputs(notes.rendered.c_str(), stderr);
  if (!app) {
    if (!load_error.empty()) std::fprintf(stderr, "%s\n", load_error.c_str());
    return kExitBadInput;
  }
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "arbc docs: cannot create '%s': %s\n", out_dir.c_str(),
                 ec.message().c_str());
    return kExitBadInput;
  }
  std::filesystem::path dir(out_dir);
  docs::DocsInput doc{&app.value(), verification_text(*app, input), "app.svg", ""};
  size_t elements = docs::diagram_elements(*app);
  if (elements > docs::kMaxDiagramElements) {
    // Graphviz would run for minutes and nobody could read the result: tables only.
    std::string why = "The diagram is skipped for size: " + std::to_string(app->modules.size()) +
                      " modules, " + std::to_string(app->arbitrated_ports.size()) +
                      " arbitrated ports and " + std::to_string(app->connections.size()) +
                      " connections (" + std::to_string(elements) + " elements, more than " +
                      std::to_string(docs::kMaxDiagramElements) + ").";
    doc.diagram_svg.clear();
    doc.diagram_note = why + " The tables below describe the whole application.";
    // Drawings from an earlier, smaller run would contradict index.md.
    for (const char* stale : {"app.dot", "app.svg", "app.mmd"})
      std::filesystem::remove(dir / stale, ec);
    if (!write_file(dir / "index.md", docs::render_index_markdown(doc))) {
      std::fprintf(stderr, "arbc docs: cannot write into '%s'\n", out_dir.c_str());
      return kExitBadInput;
    }
    std::printf("%s\nwrote %s/index.md\n", why.c_str(), out_dir.c_str());
    return kExitOk;
  }
  std::string dot = docs::render_dot(*app);
  std::string svg, error;
  if (!docs::render_svg(dot, &svg, &error)) {
    std::fprintf(stderr, "arbc docs: %s\n", error.c_str());
    return kExitRuntimeFailure;
  }
  bool ok = write_file(dir / "index.md", docs::render_index_markdown(doc)) &&
            write_file(dir / "app.dot", dot) && write_file(dir / "app.svg", svg) &&
            write_file(dir / "app.mmd", docs::render_mermaid(*app));
  if (!ok) {
    std::fprintf(stderr, "arbc docs: cannot write into '%s'\n", out_dir.c_str());
    return kExitBadInput;
  }
  std::printf("wrote %s/index.md, app.dot, app.svg, app.mmd\n", out_dir.c_str());
  return kExitOk;
}

}  // namespace arbc::cli
