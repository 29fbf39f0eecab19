// arbc docs SPEC|APP.json [-o DIR]: index.md, app.dot, app.svg, app.mmd.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/commands.h"
#include "cli/load_app.h"
#include "compiler/docs/graph_docs.h"
#include "compiler/docs/markdown_docs.h"

namespace arbc::cli {

namespace {

bool write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

}  // namespace

int docs_command(std::span<char*> args) {
  CLI::App cli{"Write Markdown, Graphviz (DOT and SVG) and Mermaid documentation of an app.",
               "arbc docs"};
  std::string input;
  std::string out_dir = "docs-out";
  cli.add_option("SPEC", input, "the spec (or a built app.json)")->required();
  cli.add_option("-o,--output", out_dir, "directory to write into (default: docs-out)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return cli.exit(e) == 0 ? kExitOk : kExitBadInput;
  }

  LoadedApp loaded = load_app(input);
  if (!loaded.ok) {
    std::fputs(loaded.diagnostics.c_str(), stderr);
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
  std::string dot = docs::render_dot(loaded.app);
  std::string svg, error;
  if (!docs::render_svg(dot, &svg, &error)) {
    std::fprintf(stderr, "arbc docs: %s\n", error.c_str());
    return kExitRuntimeFailure;
  }
  docs::DocsInput doc{&loaded.app, loaded.verdicts, "app.svg"};
  bool ok = write_file(dir / "index.md", docs::render_index_markdown(doc)) &&
            write_file(dir / "app.dot", dot) && write_file(dir / "app.svg", svg) &&
            write_file(dir / "app.mmd", docs::render_mermaid(loaded.app));
  if (!ok) {
    std::fprintf(stderr, "arbc docs: cannot write into '%s'\n", out_dir.c_str());
    return kExitBadInput;
  }
  std::printf("wrote %s/index.md, app.dot, app.svg, app.mmd\n", out_dir.c_str());
  return kExitOk;
}

}  // namespace arbc::cli
