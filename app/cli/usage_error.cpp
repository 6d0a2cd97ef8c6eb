#include "app/cli/usage_error.h"

#include "app/cli/failure.h"
#include "app/scene/json_reader.h" // closest_match

#include <cstdio>
#include <sstream>

namespace tumble::app {
namespace {

// The subcommand the user was in when the parse failed, or nullptr.
const CLI::App* chosen_subcommand(const CLI::App& app) {
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub->parsed()) return sub;
    return nullptr;
}

// Every spelling a token could have meant: the options of `where` ("--fps", "-o") and, at the
// top level, the subcommands.
std::vector<std::string> spellings(const CLI::App& app, const CLI::App* where) {
    std::vector<std::string> out;
    const CLI::App& in = where ? *where : app;
    for (const CLI::Option* o : in.get_options()) {
        for (const std::string& n : o->get_lnames()) out.push_back("--" + n);
        for (const std::string& n : o->get_snames()) out.push_back("-" + n);
    }
    if (!where)
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
            out.push_back(sub->get_name());
    return out;
}

// The tokens CLI11 did not expect, from its message "... not expected: a b".
std::vector<std::string> unexpected_tokens(const std::string& what) {
    std::vector<std::string> out;
    const std::size_t colon = what.rfind(": ");
    if (what.find("not expected") == std::string::npos || colon == std::string::npos) return out;
    std::istringstream words(what.substr(colon + 2));
    for (std::string w; words >> w;) out.push_back(w.substr(0, w.find('=')));
    return out;
}

} // namespace

int report_usage_error(const CLI::App& app, const CLI::ParseError& error) {
    const CLI::App* where = chosen_subcommand(app);
    std::string guess;
    for (const std::string& token : unexpected_tokens(error.what()))
        if (guess.empty()) guess = closest_match(token, spellings(app, where));
    std::fprintf(stderr, "tumble: error: %s%s\n", error.what(),
                 guess.empty() ? "" : (" (did you mean \"" + guess + "\"?)").c_str());
    std::fprintf(stderr, "Run 'tumble%s%s --help' for the options.\n", where ? " " : "",
                 where ? where->get_name().c_str() : "");
    return kBadInput;
}

int report_missing_command(const CLI::App& app) {
    std::fprintf(stderr, "%s\ntumble: error: no command given (see the list above)\n",
                 app.help().c_str());
    return kBadInput;
}

} // namespace tumble::app
