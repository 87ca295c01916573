namespace Billiards.App.Rendering;

/// <summary>GLSL 3.30 core sources of the renderer's programs.</summary>
internal static class Shaders
{
    public const string LitVertex = """
        #version 330 core
        in vec3 aPosition;
        in vec3 aNormal;
        in vec2 aUv;
        in vec3 aColor;
        uniform mat4 uModel;
        uniform mat4 uViewProj;
        out vec3 vWorld;
        out vec3 vNormal;
        out vec2 vUv;
        out vec3 vColor;
        void main() {
            vec4 world = uModel * vec4(aPosition, 1.0);
            vWorld = world.xyz;
            // Model matrices here rotate, translate and scale uniformly: mat3 keeps normals' directions.
            vNormal = mat3(uModel) * aNormal;
            vUv = aUv;
            vColor = aColor;
            gl_Position = uViewProj * world;
        }
        """;

    // Lighting (linear light, then an exponential tone curve and gamma): the seed's four lights.
    // Three lamps over the bed (Lambert + Blinn-Phong highlights); the fourth light, 1 cm over the
    // centre of the bed, is a weak fill without falloff. Nothing here loops over the balls: a
    // software rasteriser (Mesa llvmpipe) runs every iteration of such a loop for every pixel
    // whether a lane needs it or not, which made a 1280x720 frame cost over a second of CPU. The
    // balls' shadows are small decals on the bed instead (ShadowFragment).
    private const string Shade = """
        uniform vec3 uEye;
        uniform vec4 uLamps[3];
        uniform vec4 uFill;
        uniform vec4 uBaseColor;
        uniform vec3 uSpecular;
        uniform float uShininess;
        uniform float uReflect;
        uniform float uAmbient;
        uniform float uExposure;

        vec3 shade(vec3 world, vec3 normal, vec3 albedo) {
            vec3 n = normalize(normal);
            vec3 v = normalize(uEye - world);
            if (dot(n, v) < 0.0 && uReflect == 0.0) n = -n;
            vec3 color = albedo * uAmbient;
            for (int k = 0; k < 3; k++) {
                vec3 toLamp = uLamps[k].xyz - world;
                float d2 = dot(toLamp, toLamp);
                vec3 l = toLamp * inversesqrt(d2);
                float ndotl = max(dot(n, l), 0.0);
                vec3 h = normalize(l + v);
                float spec = pow(max(dot(n, h), 0.0), uShininess) * (uShininess + 8.0) / 25.0;
                color += (uLamps[k].w * ndotl / d2) * (albedo + uSpecular * spec);
            }
            vec3 lf = normalize(uFill.xyz - world);
            color += uFill.w * max(dot(n, lf), 0.0) * albedo;
            // A dim room reflected by glossy surfaces (balls), stronger at grazing angles.
            if (uReflect > 0.0) {
                vec3 r = reflect(-v, n);
                vec3 room = mix(vec3(0.05, 0.04, 0.035), vec3(0.35, 0.33, 0.3), smoothstep(-0.2, 0.8, r.z));
                float fresnel = uReflect + (1.0 - uReflect) * pow(1.0 - max(dot(n, v), 0.0), 5.0);
                color = mix(color, room, fresnel * 0.5);
            }
            vec3 mapped = vec3(1.0) - exp(-color * uExposure);
            return pow(mapped, vec3(1.0 / 2.2));
        }
        """;

    // Balls and the cue: lit per pixel (they are small on screen; their highlights need it).
    public const string LitFragment = """
        #version 330 core
        in vec3 vWorld;
        in vec3 vNormal;
        in vec2 vUv;
        in vec3 vColor;
        uniform int uUseTexture;
        uniform sampler2D uTexture;
        out vec4 fragColor;
        """ + Shade + """
        void main() {
            vec4 base = uBaseColor * vec4(vColor, 1.0);
            if (uUseTexture != 0) base *= texture(uTexture, vUv);
            fragColor = vec4(shade(vWorld, vNormal, base.rgb), base.a);
        }
        """;

    // The table: lit at the vertices (its mesh is refined so that the light varies smoothly), so a
    // pixel costs only the interpolation. The table covers most of the screen; lit per pixel it
    // cost several times the budget of a frame on a two-core software rasteriser.
    public const string GouraudVertex = """
        #version 330 core
        in vec3 aPosition;
        in vec3 aNormal;
        in vec2 aUv;
        in vec3 aColor;
        uniform mat4 uModel;
        uniform mat4 uViewProj;
        uniform vec3 uEmissive;
        out vec4 vShaded;
        out vec3 vWorld;
        """ + Shade + """
        void main() {
            vec4 world = uModel * vec4(aPosition, 1.0);
            vec4 base = uBaseColor * vec4(aColor, 1.0);
            vShaded = uEmissive.r > 0.0 ? vec4(uEmissive, 1.0) : vec4(shade(world.xyz, mat3(uModel) * aNormal, base.rgb), base.a);
            vWorld = world.xyz;
            gl_Position = uViewProj * world;
        }
        """;

    // The lit colour times a detail texture (cloth weave, wood grain, floor boards; a byte holds
    // half the factor). Mapping 1 lays it across the bed's plane; 2 runs it along the rail the
    // point belongs to (x on the long rails, y on the short ones), with height for the sides.
    // Each mapping is a program of its own: a software rasteriser (llvmpipe) took both branches'
    // texture samples for every pixel of a branch on a uniform, and the table's texturing was
    // most of a moving frame's cost.
    public static string GouraudFragment(int mapping) => "#version 330 core\n#define DETAIL " + mapping.ToString(System.Globalization.CultureInfo.InvariantCulture) + "\n" + """
        in vec4 vShaded;
        in vec3 vWorld;
        uniform float uDetailRepeat;
        uniform vec2 uHalf;
        uniform sampler2D uTexture;
        out vec4 fragColor;
        void main() {
            float m = 1.0;
        #if DETAIL == 1
            m = 2.0 * texture(uTexture, vWorld.xy * uDetailRepeat).r;
        #elif DETAIL == 2
            bool alongX = abs(vWorld.y) - uHalf.y > abs(vWorld.x) - uHalf.x;
            vec2 a = alongX ? vWorld.xy : vWorld.yx;
            m = 2.0 * texture(uTexture, vec2(a.x, a.y + vWorld.z) * uDetailRepeat).r;
        #endif
            fragColor = vec4(vShaded.rgb * m, vShaded.a);
        }
        """;

    // A ball's shadow on the bed: a quad around the ball at bed height, multiplied into the frame.
    // The soft shadow is found analytically: a lamp is a disc of angular radius atan(r/d) and the
    // ball a disc of angular radius asin(R/|c-p|); the covered part of the lamp is estimated from
    // the angle between their centres. The bed's ambient light is darkened by the ball's sphere
    // occlusion. The factor is the ratio of the shadowed to the unshadowed light on the cloth,
    // taken through the display gamma because it multiplies tone-mapped colour.
    public const string ShadowVertex = """
        #version 330 core
        in vec3 aPosition;
        uniform mat4 uViewProj;
        out vec3 vWorld;
        void main() {
            vWorld = aPosition;
            gl_Position = uViewProj * vec4(aPosition, 1.0);
        }
        """;

    public const string ShadowFragment = """
        #version 330 core
        in vec3 vWorld;
        uniform vec4 uBall;
        uniform vec4 uLamps[3];
        uniform float uLampRadius;
        uniform float uAmbient;
        out vec4 fragColor;

        void main() {
            vec3 p = vWorld;
            vec3 toBall = uBall.xyz - p;
            float dist = length(toBall);
            float r = uBall.w;
            float ratio = r / max(dist, r);
            float lit = uAmbient * (1.0 - max(toBall.z / max(dist, r), 0.0) * ratio * ratio);
            float open = uAmbient;
            for (int k = 0; k < 3; k++) {
                vec3 toLamp = uLamps[k].xyz - p;
                float lampDist = length(toLamp);
                vec3 l = toLamp / lampDist;
                float irradiance = uLamps[k].w * max(l.z, 0.0) / (lampDist * lampDist);
                float lampAngle = atan(uLampRadius / lampDist);
                float ballAngle = asin(min(r / max(dist, r), 1.0));
                float separation = acos(clamp(dot(toBall / max(dist, 1e-6), l), -1.0, 1.0));
                float covered = 1.0 - smoothstep(ballAngle - lampAngle, ballAngle + lampAngle, separation);
                float most = min(1.0, (ballAngle * ballAngle) / (lampAngle * lampAngle));
                lit += irradiance * (1.0 - covered * most);
                open += irradiance;
            }
            float f = pow(clamp(lit / open, 0.0, 1.0), 1.0 / 2.2);
            fragColor = vec4(f, f, f, 1.0);
        }
        """;

    public const string LineVertex = """
        #version 330 core
        in vec4 aClip;
        in vec3 aColor;
        out vec3 vColor;
        void main() {
            vColor = aColor;
            gl_Position = aClip;
        }
        """;

    public const string LineFragment = """
        #version 330 core
        in vec3 vColor;
        out vec4 fragColor;
        void main() { fragColor = vec4(vColor, 1.0); }
        """;

    // HUD: pixel coordinates; kind 0 = solid, 1 = font texture (red channel is ink), 2 = filled
    // disc (uv in [-1, 1]), 3 = ring; edges antialiased over one pixel.
    public const string HudVertex = """
        #version 330 core
        in vec2 aPosition;
        in vec2 aUv;
        in vec4 aColor;
        in float aKind;
        uniform vec2 uScreen;
        out vec2 vUv;
        out vec4 vColor;
        flat out int vKind;
        void main() {
            vUv = aUv;
            vColor = aColor;
            vKind = int(aKind + 0.5);
            gl_Position = vec4(aPosition.x / uScreen.x * 2.0 - 1.0, 1.0 - aPosition.y / uScreen.y * 2.0, 0.0, 1.0);
        }
        """;

    public const string HudFragment = """
        #version 330 core
        in vec2 vUv;
        in vec4 vColor;
        flat in int vKind;
        uniform sampler2D uFont;
        out vec4 fragColor;
        void main() {
            float alpha = 1.0;
            if (vKind == 1) {
                alpha = texture(uFont, vUv).r;
            } else if (vKind >= 2) {
                float r = length(vUv);
                float w = fwidth(r);
                alpha = 1.0 - smoothstep(1.0 - w, 1.0, r);
                if (vKind == 3) alpha *= smoothstep(0.86 - w, 0.86, r);
            }
            fragColor = vec4(vColor.rgb, vColor.a * alpha);
        }
        """;
}
