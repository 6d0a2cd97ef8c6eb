// `tumble study --quick` as CI runs it: the files it promises exist and parse, every registered
// integrator is studied on every problem, measured orders match theory, divergences are recorded as
// results, and the recommendation table follows from the rows (checked here independently).
#include "app/study/study.h"
#include "physics/integrator.h"
#include "render/png_io.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

struct CsvRow {
    std::map<std::string, std::string> f;
    double num(const std::string& key) const { return std::stod(f.at(key)); }
};

std::vector<CsvRow> read_csv(const fs::path& p) {
    std::istringstream in(read_text(p));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
    std::vector<CsvRow> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        CsvRow r;
        std::size_t i = 0;
        for (std::string cell; i < header.size(); ++i) {
            std::getline(s, cell, ',');
            r.f[header[i]] = cell;
        }
        rows.push_back(r);
    }
    return rows;
}

// The recommendation rule of docs/study.md, written again from the CSV: the cheapest row whose
// orientation error (max over [0, T]; the position error for a contact problem) meets the target
// at its step and at every finer step of the same integrator, none of them diverged.
const CsvRow* cheapest(const std::vector<CsvRow>& rows, const std::string& problem, double target) {
    bool contacts = false;
    for (const app::study::Problem& p : app::study::problems())
        if (p.name == problem) contacts = p.contacts;
    const char* error = contacts ? "pos_max" : "ori_max";
    const CsvRow* best = nullptr;
    for (const CsvRow& r : rows) {
        if (r.f.at("problem") != problem) continue;
        bool ok = true;
        for (const CsvRow& o : rows)
            if (o.f.at("problem") == problem && o.f.at("integrator") == r.f.at("integrator") &&
                o.num("dt") <= r.num("dt") &&
                (o.f.at("diverged") == "1" || !(o.num(error) <= target)))
                ok = false;
        if (ok && (!best || r.num("cost_s") < best->num("cost_s"))) best = &r;
    }
    return best;
}

// Pixels clearly coloured (not white, grey or black): the plotted lines.
int coloured_pixels(const render::Image& img) {
    int n = 0;
    for (std::size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
        const int mx = std::max({img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]});
        const int mn = std::min({img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]});
        if (mx - mn > 60) ++n;
    }
    return n;
}

// The contacts' work-precision view (issue 28): every setting on both scenes; the fixed settings
// cost exactly what they say (480x1: 2 substeps of 1 + 1 sweeps, 4 sweeps per contact point per
// step; 1440x3: 6 substeps of 3 + 2, 30), and on the column of boxes a tighter contact tolerance
// buys more substeps and a smaller sinking.
void check_contact_effort(const fs::path& out, const std::string& report) {
    const std::vector<CsvRow> rows = read_csv(out / "contact_effort.csv");
    ASSERT_EQ(rows.size(), 2u * 7u);
    std::map<std::string, const CsvRow*> stack;
    for (const CsvRow& row : rows) {
        const std::string& setting = row.f.at("setting");
        EXPECT_GT(row.num("us_per_step"), 0.0) << setting;
        if (setting == "480x1" || setting == "1440x3") {
            const bool old = setting == "480x1";
            EXPECT_EQ(row.num("substeps_per_body"), old ? 2.0 : 6.0) << row.f.at("scene");
            EXPECT_EQ(row.num("sweeps_per_point"), old ? 2.0 * 2.0 : 6.0 * 5.0)
                << row.f.at("scene");
        }
        if (row.f.at("scene") == "stack") stack[setting] = &row;
    }
    const CsvRow& loose = *stack.at("tolerance 1 mm");
    const CsvRow& tight = *stack.at("tolerance 0.01 mm");
    std::printf("[measured] column of 10: 1 mm: %g mm, %g substeps; 0.01 mm: %g mm, %g substeps\n",
                loose.num("error_mm"), loose.num("substeps_per_body"), tight.num("error_mm"),
                tight.num("substeps_per_body"));
    EXPECT_GT(tight.num("substeps_per_body"), loose.num("substeps_per_body"));
    EXPECT_LT(tight.num("error_mm"), loose.num("error_mm"));
    EXPECT_NE(report.find("## Contacts: what each effort setting buys"), std::string::npos);
    EXPECT_NE(report.find("(plots/contact-effort.png)"), std::string::npos);
    EXPECT_GT(coloured_pixels(render::read_png(out / "plots" / "contact-effort.png")), 500);
}

// One quick study checked every way (a quick study is the suite's costliest run: 71 s in Release,
// 363 s under ASan): its outputs, missing parent folders created (the one output rule of issue 14),
// and the same errors from one thread as from two.
TEST(Study, QuickStudyWritesConsistentOutputs) {
    const fs::path dir = scratch_dir();
    const CliResult r = run_tumble(dir, "study --quick -o deep/er/out --threads 2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path out = dir / "deep/er/out";
    EXPECT_NE(r.out.find("recommendation"), std::string::npos) << r.out;

    // Every row in both formats, every registered integrator on every problem.
    const std::vector<CsvRow> rows = read_csv(out / "study.csv");
    const nlohmann::json j = nlohmann::json::parse(read_text(out / "study.json"));
    ASSERT_EQ(j["rows"].size(), rows.size());
    std::set<std::string> problems;
    for (const CsvRow& row : rows) problems.insert(row.f.at("problem"));
    EXPECT_GE(problems.size(), 6u);
    // Except the pairs refused at build time, each skipped with its reason: `exact` (which
    // refuses applied torques) on exactly the problems whose bodies have a torque.
    const std::string report = read_text(out / "report.md");
    int skips = 0;
    for (const app::study::Problem& problem : app::study::problems()) {
        bool torqued = false;
        for (const physics::BodyDef& b : problem.bodies())
            torqued |= b.applied_torque != physics::Vec3::Zero();
        for (const physics::IntegratorInfo& info : physics::integrators()) {
            int count = 0;
            for (const CsvRow& row : rows)
                count += row.f.at("problem") == problem.name && row.f.at("integrator") == info.name;
            std::string reason;
            for (const auto& k : j["skipped"])
                if (k["problem"] == problem.name && k["integrator"] == info.name)
                    reason = k["reason"];
            if (torqued && info.refuses_torque) {
                ++skips;
                EXPECT_EQ(count, 0) << problem.name << " / " << info.name;
                EXPECT_NE(reason.find("has an applied torque"), std::string::npos) << reason;
                EXPECT_NE(report.find("Not run: `" + std::string(info.name) + "`: " + reason),
                          std::string::npos)
                    << problem.name << " / " << info.name;
            } else {
                EXPECT_TRUE(reason.empty()) << problem.name << " / " << info.name << ": " << reason;
                EXPECT_GE(count, 4) << problem.name << " / " << info.name;
            }
        }
    }
    EXPECT_EQ(static_cast<int>(j["skipped"].size()), skips);
    EXPECT_GE(skips, 1);

    // The contact map: every case for every (integrator, substeps) of the quick map, in the CSV,
    // the JSON, the report and its plot; the default settings hold the 50 m/s bullet.
    const std::vector<CsvRow> contact = read_csv(out / "contact_stability.csv");
    EXPECT_EQ(contact.size(), 13u * 2u * 2u);
    EXPECT_EQ(j["contact_stability"].size(), contact.size());
    for (const CsvRow& row : contact) {
        EXPECT_GT(row.num("dt"), 0.0) << row.f.at("case");
        if (row.f.at("case") == "bullet 50 m/s" && row.f.at("integrator") == "rk4" &&
            row.f.at("substeps") == "0") {
            EXPECT_EQ(row.f.at("holds_default"), "1");
        }
    }
    EXPECT_NE(read_text(out / "report.md").find("## Contact stability map"), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "plots" / "contact-stability.png"));

    // Divergences are rows with body, step and quantity; other rows have finite errors.
    int diverged = 0;
    for (const CsvRow& row : rows) {
        if (row.f.at("diverged") == "1") {
            ++diverged;
            EXPECT_GE(std::stoi(row.f.at("diverged_body")), 0);
            EXPECT_GE(std::stoll(row.f.at("diverged_step")), 1);
            EXPECT_FALSE(row.f.at("diverged_quantity").empty());
        } else {
            EXPECT_TRUE(std::isfinite(row.num("ori_end")) && std::isfinite(row.num("energy_max")))
                << row.f.at("problem") << " " << row.f.at("integrator") << " " << row.f.at("dt");
        }
        EXPECT_GT(row.num("ns_per_body_step"), 0.0);
    }
    // The quick grid reaches h|w| = 1 on the fast spin, where explicit methods blow up.
    TUMBLE_MEASURED(diverged, 1);
    EXPECT_GE(diverged, 1);

    // Orders: every integrator on the headline problem, and the higher-order methods wherever a
    // fit exists, against the registry's theoretical order.
    for (const auto& o : j["orders"]) {
        if (o["measured"].is_null()) continue;
        const double measured = o["measured"], theory = o["theory"];
        const double deviation = std::abs(measured - theory);
        if (o["problem"] == "intermediate-axis") {
            std::printf("[measured] order of %s on the flip = %.3f (theory %g)\n",
                        o["integrator"].get<std::string>().c_str(), measured, theory);
            EXPECT_LE(deviation, 0.2) << o["integrator"];
        } else if (theory >= 2 && o["problem"] != "intermediate-axis-20s") {
            // (Over 20 s the quick grid's steps are not yet asymptotic for the fourth-order
            // methods: rk4's error falls as h^5 there, as lesson 6 finds at 10 s, measured 5.00,
            // and splitting4's flattens at round-off, 3.14.)
            EXPECT_LE(deviation, 0.35) << o["problem"] << " / " << o["integrator"];
        }
    }

    // The order table's "theory" column gives each method's order on the free body, whatever the
    // last problem of the quick grid is (a contact problem fits order 1 for everyone): the
    // textbook orders, written here rather than read from the registry.
    for (const auto& [name, order] :
         std::vector<std::pair<std::string, int>>{{"euler", 1},
                                                  {"symplectic_euler", 1},
                                                  {"rk4", 4},
                                                  {"splitting", 2},
                                                  {"midpoint", 2},
                                                  {"splitting4", 4}})
        EXPECT_NE(report.find("| " + name + " | " + std::to_string(order) + " |"),
                  std::string::npos)
            << name << " should have theory order " << order;

    // The recommendation table (JSON and the end of report.md) follows from the rows.
    const std::string table = report.substr(report.rfind("## Recommendation"));
    ASSERT_EQ(j["recommendations"].size(), 3 * problems.size());
    for (const auto& rec : j["recommendations"]) {
        const std::string problem = rec["problem"];
        const double target = rec["target"];
        const CsvRow* expected = cheapest(rows, problem, target);
        if (!expected) {
            EXPECT_TRUE(rec["integrator"].is_null()) << problem << " " << target;
            continue;
        }
        ASSERT_FALSE(rec["integrator"].is_null()) << problem << " " << target;
        EXPECT_EQ(rec["integrator"], expected->f.at("integrator")) << problem << " " << target;
        EXPECT_EQ(rec["steps"].get<long long>(), std::stoll(expected->f.at("steps")));
        EXPECT_LE(rec["error"].get<double>(), target);
        const std::string line = "| " + problem + " | " +
                                 (target == 1e-2   ? "1e-02"
                                  : target == 1e-4 ? "1e-04"
                                                   : "1e-06") +
                                 " | " + expected->f.at("integrator") + " |";
        EXPECT_NE(table.find(line), std::string::npos) << line;
    }

    // The stability map: every integrator for every inertia case, within the searched range.
    std::set<std::string> mapped;
    for (const auto& s : j["stability"]) {
        mapped.insert(s["integrator"].get<std::string>());
        EXPECT_GE(s["h_w"].get<double>(), 1e-4);
        EXPECT_LE(s["h_w"].get<double>(), 100.0);
    }
    EXPECT_EQ(mapped.size(), physics::integrators().size());
    EXPECT_NE(report.find("## Stability map"), std::string::npos);

    // Plots: PNGs gnuplot drew, with coloured lines in them, linked from the report.
    std::vector<std::string> pngs = {"plots/energy.png", "plots/stability.png"};
    for (const std::string& p : problems) {
        pngs.push_back("plots/work-precision-" + p + ".png");
        pngs.push_back("plots/error-vs-dt-" + p + ".png");
    }
    for (const std::string& png : pngs) {
        EXPECT_NE(report.find("(" + png + ")"), std::string::npos) << png;
        const render::Image img = render::read_png(out / png);
        EXPECT_EQ(img.width, 900) << png;
        EXPECT_GT(coloured_pixels(img), 500) << png;
    }
    check_contact_effort(out, report);

    // Each row is computed by one thread from its own state: only the timings may change.
    ASSERT_EQ(run_tumble(dir, "study --quick -q -o one --threads 1").exit_code, 0);
    const std::vector<CsvRow> single = read_csv(dir / "one/study.csv");
    ASSERT_EQ(single.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        for (const auto& [key, value] : single[i].f) {
            if (key == "ns_per_body_step" || key == "steps_per_second" || key == "cost_s") continue;
            EXPECT_EQ(value, rows[i].f.at(key)) << "row " << i << " column " << key;
        }
    }
}

TEST(Study, UnwritableOutputIsBadInput) {
    const fs::path dir = scratch_dir();
    write_text(dir / "file", "not a folder");
    const CliResult r = run_tumble(dir, "study --quick -o file/sub");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("file/sub"), std::string::npos) << r.err;
}

} // namespace
} // namespace tumble::test
