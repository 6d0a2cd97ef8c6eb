#pragma once
// How the camera moves, as the scene file's render.camera describes it (app/view/camera.h
// evaluates it at each frame's time). Four kinds (docs/scene-format.md, render.camera):
//   fixed   position, target, up, fov_deg
//   orbit   circles a centre at a fixed radius and height, one turn per `period` seconds
//   follow  rides along with a body at a fixed offset, looking at it (or, with "track", stays
//           put and turns to look at it)
//   path    keyframes {t, position, target, fov_deg}, interpolated smoothly (cubic Hermite with
//           Catmull-Rom tangents, easing in and out at the first and last key)
//   auto    one fixed camera that keeps every dynamic body in view for the whole run, chosen by
//           a pre-pass (app/run/auto_camera.h); also what a scene without a camera gets
//   poinsot one fixed camera that frames Poinsot's construction of render.poinsot at t = 0
//           (`render --poinsot BODY`, unless --camera is given; app/view/poinsot.h)
// A camera is a pure function of time and the followed body's position: frame k's camera needs
// no history, so a still of frame k is the same as frame k of a video.
#include "render/scene_view.h"

#include <string>
#include <vector>

namespace tumble::app {

struct CameraKey {
    double t = 0.0; // s
    glm::dvec3 position{0.0}, target{0.0};
    double fov_deg = 45.0;
};

struct CameraRig {
    // Auto: a fixed camera chosen by a pre-pass over the run (app/run/auto_camera.h), the mode
    // of a scene that gives no camera; Poinsot: one that frames the construction.
    // frame_automatically() turns either into Fixed before drawing.
    enum class Mode { Fixed, Orbit, Follow, Path, Auto, Poinsot };
    Mode mode = Mode::Auto;
    render::Camera base; // the fixed camera; up, fov and clip planes for every mode

    // orbit
    glm::dvec3 center{0.0};   // circled point, also looked at
    double radius = 0.0;      // horizontal distance from the centre, m
    double height = 0.0;      // camera height above the centre, m
    double period = 0.0;      // s per turn; negative turns clockwise seen from above
    double start_angle = 0.0; // rad, of the camera around the centre at t = 0

    // follow
    std::string follow_name; // body name as given in the scene (or its index as text)
    std::string follow_path; // JSON path of that name, for the error if no body has it
    int follow_body = -1;    // resolved index
    glm::dvec3 offset{0.0};  // camera position - body position, world axes, m
    bool track = false;      // camera stays at base.position and only turns

    // path
    std::vector<CameraKey> keys; // t strictly increasing, at least two

    // auto
    glm::dvec3 auto_direction{0.0}; // from the target towards the camera; 0: base's direction
    double auto_margin = 0.1;       // of the half-frame, kept free on every side

    bool needs_body() const { return mode == Mode::Follow; }
};

// A camera given on the command line (`render --camera TEXT`, named `option` in errors) into
// `rig`: "X,Y,Z:X,Y,Z[:FOV]" is a fixed camera at the first point looking at the second, metres,
// with a vertical field of view in degrees (else the rig's); "auto" frames every moving body
// for the whole run; "poinsot" frames Poinsot's construction. Throws SceneError naming the option
// and the form expected.
void read_camera_option(const std::string& text, const std::string& option, CameraRig& rig);

// Resolves rig.follow_name against the bodies' names (or an index); throws SceneError naming
// `file` and the JSON path of the name when no body matches.
void resolve_followed_body(CameraRig& rig, const std::vector<std::string>& body_names,
                           const std::string& file);

} // namespace tumble::app
