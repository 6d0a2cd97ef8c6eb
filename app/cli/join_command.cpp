// `tumble join`: MP4 shards of one run (`tumble render --frames A:B`) into one video, without
// re-encoding (app/cluster/video_join.h). The shards may be given in any order; they are checked
// to belong together before anything is written.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/cluster/video_join.h"
#include "app/run/stale_temporaries.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

struct JoinCommand {
    std::vector<std::string> parts;
    std::string output;
    bool quiet = false;
};

int run_join(const JoinCommand& cmd) {
    remove_stale_temporaries_for(cmd.output, cmd.quiet);
    const JoinResult r = join_videos(cmd.parts, cmd.output);
    if (!cmd.quiet) {
        std::fprintf(stderr, "tumble: joined %zu shard%s, frames %s of %lld, without re-encoding\n",
                     r.order.size(), r.order.size() == 1 ? "" : "s", r.tag.range.text().c_str(),
                     static_cast<long long>(r.tag.frames));
        if (r.tag.range.first != 0 || r.tag.range.end != r.tag.frames)
            std::fprintf(stderr, "tumble: note: the run has frames 0:%lld; this is part of it\n",
                         static_cast<long long>(r.tag.frames));
        std::fprintf(stderr, "tumble: wrote %s\n", cmd.output.c_str());
    }
    return kOk;
}

} // namespace

Subcommand add_join_command(CLI::App& app) {
    auto cmd = std::make_shared<JoinCommand>();
    CLI::App* j = app.add_subcommand(
        "join", "concatenate MP4 shards of one run (render --frames A:B) without re-encoding");
    j->add_option("shards", cmd->parts, "the shards' .mp4 files, in any order")->required();
    j->add_option("-o,--output", cmd->output, "the joined video, .mp4")->required();
    j->add_flag("-q,--quiet", cmd->quiet, "no summary");
    return {[j] { return j->parsed(); }, [cmd] { return run_join(*cmd); }};
}

} // namespace tumble::app
