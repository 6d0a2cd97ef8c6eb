// tumble_main() only collects the subcommands (each in app/cli/<name>_command.cpp), parses the
// command line and runs the one given through run_guarded(), which maps every failure to an exit
// code (app/cli/failure.h).
#include "app/cli/tumble_main.h"

#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/cli/usage_error.h"
#include "render/video_sink.h"

#include <vector>

namespace tumble::app {

int tumble_main(int argc, char** argv) {
    CLI::App app{"tumble: rigid-body dynamics rendered headlessly to video or PNG"};
    app.require_subcommand(0, 1);
    const std::vector<Subcommand> commands = {
        add_version_flag(app),    add_render_command(app), add_simulate_command(app),
        add_explain_command(app), add_scenes_command(app), add_test_command(app),
        add_diff_command(app),    add_study_command(app),  add_schema_command(app),
        add_plot_command(app),    add_join_command(app),   add_shards_command(app),
        add_sweep_command(app),
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& h) {
        return app.exit(h);
    } catch (const CLI::ParseError& err) {
        return report_usage_error(app, err);
    }
    render::quiet_video_logs();
    for (const Subcommand& c : commands)
        if (c.chosen()) return run_guarded(c.run);
    return report_missing_command(app);
}

} // namespace tumble::app
