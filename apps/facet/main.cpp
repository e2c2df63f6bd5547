// The facet program: parses the command line and runs a subcommand. Errors become one line
// on stderr and exit code 2; the parser's own are put in facet's words (usage_errors.hpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "bench_command.hpp"
#include "facet/error.hpp"
#include "facet/version.hpp"
#include "help_format.hpp"
#include "info_command.hpp"
#include "process_memory.hpp"
#include "render_batch.hpp"
#include "render_command.hpp"
#include "thumbnail_command.hpp"
#include "usage_errors.hpp"
#include "view_command.hpp"

namespace {

constexpr int kUsageError = 2;

int fail(const std::string& message) {
  std::fprintf(stderr, "facet: error: %s\n", message.c_str());
  return kUsageError;
}

}  // namespace

int main(int argc, char** argv) {
  facet::cli::use_memory_for_short_run();
  // Named, so that usage lines say `facet` rather than the path the program was run by.
  CLI::App app{"facet: a CPU software rasterizer. Renders 3D scenes without a GPU.", "facet"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("facet ") + facet::version(),
                       "Print the version and exit");
  app.footer("Run 'facet COMMAND --help' for a command's options; 'man facet' for examples.");
  facet::cli::RenderOptions render_options;
  CLI::App* render = facet::cli::add_render_command(app, render_options);
  facet::cli::ThumbnailOptions thumbnail_options;
  CLI::App* thumbnail = facet::cli::add_thumbnail_command(app, thumbnail_options);
  facet::cli::ViewOptions view_options;
  CLI::App* view = facet::cli::add_view_command(app, view_options);
  facet::cli::InfoOptions info_options;
  CLI::App* info = facet::cli::add_info_command(app, info_options);
  facet::cli::BenchOptions bench_options;
  CLI::App* bench = facet::cli::add_bench_command(app, bench_options);
  // Set after the commands are added, which copy the formatter they find: theirs stays CLI11's.
  auto format = std::make_shared<facet::cli::HelpFormat>();
  format->column_width(14);
  app.formatter(format);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    // The program's help lists the commands, one line each; help() hands `facet render --help`
    // to the command named, which lists its own options.
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion&) {
    std::printf("facet %s\n", facet::version());
    return 0;
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(facet::cli::usage_message(e, app, argc, argv));
  }
  try {
    if (render->parsed()) return facet::cli::run_render_command(render_options);
    if (thumbnail->parsed()) return facet::cli::run_thumbnail(thumbnail_options);
    if (info->parsed()) return facet::cli::run_info(info_options);
    if (bench->parsed()) return facet::cli::run_bench(bench_options);
    if (view->parsed()) return facet::cli::run_view(view_options);
  } catch (const facet::Error& e) {
    return fail(e.what());
  } catch (const std::exception& e) {
    return fail(std::string("unexpected: ") + e.what());
  }
  return 0;
}
