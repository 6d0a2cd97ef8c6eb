#include "app/study/contact_check.h"
#include "physics/integrator.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tumble::app::study {

using physics::Model;
using physics::ShapeKind;
using physics::State;
using physics::Vec3;

namespace {

// The map's next case up of `family` for a scene value, or none when the value is below the first.
std::optional<ContactCase> next_case(const std::string& family, double value) {
    std::optional<ContactCase> last;
    for (const ContactCase& c : contact_cases()) {
        if (c.family != family) continue;
        if (c.parameter >= value) return c;
        last = c;
    }
    return last; // beyond the map: its largest case
}

bool is_dynamic_box(const Model& m, int i) {
    return m.is_dynamic(i) && m.shape[i].kind == ShapeKind::Box;
}

// Half extents of a box's world bounding box: e_k = sum_j |R_kj| h_j.
Vec3 world_half_extents(const Model& m, const State& s, int i) {
    const physics::Mat3 r = physics::body_pose(m, s, i).orientation.toRotationMatrix();
    return r.cwiseAbs() * m.shape[i].half_extents;
}

// j rests on i: j's bottom is within 1 cm of i's top and their footprints overlap (judged on
// world bounding boxes: enough for a resemblance).
bool rests_on(const Model& m, const State& s, int j, int i) {
    const Vec3 a = world_half_extents(m, s, i);
    const Vec3 b = world_half_extents(m, s, j);
    const Vec3 d = s.x[j] - s.x[i];
    return std::abs(d.z() - (a.z() + b.z())) < 0.01 && std::abs(d.x()) < a.x() + b.x() &&
           std::abs(d.y()) < a.y() + b.y();
}

// Tallest column of boxes and the largest heavy-on-light ratio within any column.
void columns(const Model& m, const State& s, int& tallest, double& ratio) {
    const int n = m.body_count();
    std::vector<int> order;
    for (int i = 0; i < n; ++i)
        if (is_dynamic_box(m, i)) order.push_back(i);
    if (order.size() > 4096) return; // pairwise: only for scenes of a size one stacks by hand
    std::sort(order.begin(), order.end(), [&](int a, int b) { return s.x[a].z() < s.x[b].z(); });
    std::vector<int> height(n, 1);
    for (std::size_t q = 0; q < order.size(); ++q)
        for (std::size_t p = 0; p < q; ++p) {
            const int i = order[p], j = order[q];
            if (!rests_on(m, s, j, i)) continue;
            height[j] = std::max(height[j], height[i] + 1);
            ratio = std::max(ratio, m.mass[j] / m.mass[i]);
        }
    for (int i : order) tallest = std::max(tallest, height[i]);
}

bool sphere_rests_on_plane(const Model& m, const State& s, int i) {
    if (!m.is_dynamic(i) || m.shape[i].kind != ShapeKind::Sphere) return false;
    for (int p = 0; p < m.body_count(); ++p) {
        if (m.shape[p].kind != ShapeKind::Plane) continue;
        const Vec3 n = s.q[p] * Vec3::UnitZ();
        const double gap = n.dot(s.x[i] - s.x[p]) - m.shape[i].radius;
        if (std::abs(gap) < 1e-3 && s.v[i].norm() < 0.05) return true;
    }
    return false;
}

} // namespace

std::vector<ContactCheck> check_contact_regions(const Model& m, const State& s) {
    std::vector<ContactCheck> out;
    if (!m.passes.contacts) return out;
    int tallest = 0;
    double ratio = 0.0, speed = 0.0, spin = 0.0;
    bool static_box = false, resting_sphere = false;
    columns(m, s, tallest, ratio);
    for (int i = 0; i < m.body_count(); ++i) {
        static_box |= !m.is_dynamic(i) && m.shape[i].kind == ShapeKind::Box;
        if (!m.is_dynamic(i)) continue;
        speed = std::max(speed, s.v[i].norm());
        spin = std::max(spin, s.w[i].norm());
        resting_sphere |= sphere_rests_on_plane(m, s, i);
    }
    const auto add = [&](const std::string& family, double value, std::string why) {
        if (const auto c = next_case(family, value)) out.push_back({*c, std::move(why), {}});
    };
    char buf[96];
    if (tallest >= 3) {
        std::snprintf(buf, sizeof buf, "a column of %d boxes", tallest);
        add("stack", tallest, buf);
    }
    if (ratio >= 10.0) {
        std::snprintf(buf, sizeof buf, "a box %.3g times heavier than the one it rests on", ratio);
        add("ratio", ratio, buf);
    }
    if (speed >= 1.0 && static_box) {
        std::snprintf(buf, sizeof buf, "a body at %.3g m/s and a static box", speed);
        add("bullet", speed, buf);
    }
    if (spin >= 100.0) {
        std::snprintf(buf, sizeof buf, "a body spinning at %.3g rad/s", spin);
        add("top", spin, buf);
    }
    if (resting_sphere) add("rest", 0.0, "a sphere resting on a plane");
    const std::string integrator(physics::integrator_info(m.integrator).name);
    for (ContactCheck& c : out)
        c.run = run_contact_case(c.c, integrator, m.dt, m.contact.substeps, m.contact.iterations,
                                 m.contact.tolerance);
    return out;
}

} // namespace tumble::app::study
