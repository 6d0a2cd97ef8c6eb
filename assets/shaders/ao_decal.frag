// ao_decal.frag: how much of the sky a body hides from a point of the ground, as a factor that
// the blend multiplies into the colour already drawn there (glBlendFunc(GL_ZERO, GL_SRC_COLOR)).
// The whole colour is darkened, not only its ambient part: the decal cannot split what the
// ground pass summed, so kStrength keeps the contact dark without blackening sunlit ground.

in vec3 v_world;
flat in vec3 v_normal;
flat in vec4 v_occluder[3];

out vec4 frag_color;

uniform vec3 u_camera_pos;

const float kStrength = 0.6;     // darkening where the body hides the whole sky
const float kFogDistance = 60.0; // as lit.frag: distant ground fades into the sky, and so does
                                 // its darkening

void main() {
    float occlusion = ellipsoid_occlusion(v_world, v_normal, v_occluder[0], v_occluder[1],
                                          v_occluder[2]);
    vec3 view = v_world - u_camera_pos;
    float fog = 1.0 - exp(-dot(view, view) * (1.0 / (kFogDistance * kFogDistance)));
    float factor = 1.0 - kStrength * occlusion * (1.0 - fog);
    // The target holds sRGB-encoded values: multiplying one by the encoded factor multiplies
    // the light by the factor (exactly for a power curve, closely for sRGB's).
    frag_color = output_color(vec3(factor));
}
