namespace Billiards.App.Rendering;

/// <summary>GLSL 3.30 core sources of the renderer's programs.</summary>
internal static class Shaders
{
    /// <summary>Most balls a frame's shadows take into account.</summary>
    public const int MaxShadowBalls = 24;

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
    // Three lamps over the bed shade per pixel (Lambert + Blinn-Phong highlights) and cast soft
    // shadows of the balls, found analytically: a lamp is a disc of angular radius atan(r/d) and a
    // ball a disc of angular radius asin(R/|c-p|); the covered part of the lamp is estimated from
    // the angle between their centres. The fourth light, 1 cm over the centre of the bed, is a
    // weak fill without falloff. Ambient light is darkened by each ball's sphere occlusion.
    public const string LitFragment = """
        #version 330 core
        in vec3 vWorld;
        in vec3 vNormal;
        in vec2 vUv;
        in vec3 vColor;
        uniform vec3 uEye;
        uniform vec4 uLamps[3];
        uniform float uLampRadius;
        uniform vec4 uFill;
        uniform vec4 uBaseColor;
        uniform vec3 uSpecular;
        uniform float uShininess;
        uniform float uReflect;
        uniform int uUseTexture;
        uniform sampler2D uTexture;
        uniform vec4 uBalls[24];
        uniform int uBallCount;
        uniform int uSelf;
        uniform float uAmbient;
        uniform float uExposure;
        out vec4 fragColor;

        float ballVisibility(vec3 p, vec3 lampPos, float lampAngle) {
            vec3 toLamp = lampPos - p;
            float lampDist = length(toLamp);
            vec3 l = toLamp / lampDist;
            float visible = 1.0;
            for (int i = 0; i < uBallCount; i++) {
                if (i == uSelf) continue;
                vec3 toBall = uBalls[i].xyz - p;
                float dist = length(toBall);
                float r = uBalls[i].w;
                if (dist <= r || dot(toBall, l) <= 0.0 || dist >= lampDist) continue;
                float ballAngle = asin(min(r / dist, 1.0));
                float separation = acos(clamp(dot(toBall / dist, l), -1.0, 1.0));
                float covered = 1.0 - smoothstep(ballAngle - lampAngle, ballAngle + lampAngle, separation);
                float most = min(1.0, (ballAngle * ballAngle) / (lampAngle * lampAngle));
                visible *= 1.0 - covered * most;
            }
            return visible;
        }

        float ambientOcclusion(vec3 p, vec3 n) {
            float occlusion = 0.0;
            for (int i = 0; i < uBallCount; i++) {
                if (i == uSelf) continue;
                vec3 toBall = uBalls[i].xyz - p;
                float dist = max(length(toBall), uBalls[i].w);
                float ratio = uBalls[i].w / dist;
                occlusion += max(dot(n, toBall / dist), 0.0) * ratio * ratio;
            }
            return clamp(1.0 - occlusion, 0.0, 1.0);
        }

        void main() {
            vec3 n = normalize(vNormal);
            vec3 v = normalize(uEye - vWorld);
            if (dot(n, v) < 0.0 && uUseTexture == 0) n = -n;
            vec4 base = uBaseColor * vec4(vColor, 1.0);
            if (uUseTexture != 0) base *= texture(uTexture, vUv);
            vec3 albedo = base.rgb;

            vec3 color = albedo * uAmbient * ambientOcclusion(vWorld, n);
            for (int k = 0; k < 3; k++) {
                vec3 toLamp = uLamps[k].xyz - vWorld;
                float d2 = dot(toLamp, toLamp);
                vec3 l = toLamp * inversesqrt(d2);
                float ndotl = dot(n, l);
                if (ndotl <= 0.0) continue;
                float lampAngle = atan(uLampRadius / sqrt(d2));
                float shadow = ballVisibility(vWorld, uLamps[k].xyz, lampAngle);
                float irradiance = uLamps[k].w * ndotl / d2 * shadow;
                vec3 h = normalize(l + v);
                float spec = pow(max(dot(n, h), 0.0), uShininess) * (uShininess + 8.0) / 25.0;
                color += irradiance * (albedo + uSpecular * spec);
            }
            vec3 lf = normalize(uFill.xyz - vWorld);
            color += uFill.w * max(dot(n, lf), 0.0) * albedo;

            // A dim room reflected by glossy surfaces (balls), stronger at grazing angles.
            if (uReflect > 0.0) {
                vec3 r = reflect(-v, n);
                vec3 room = mix(vec3(0.05, 0.04, 0.035), vec3(0.35, 0.33, 0.3), smoothstep(-0.2, 0.8, r.z));
                float fresnel = uReflect + (1.0 - uReflect) * pow(1.0 - max(dot(n, v), 0.0), 5.0);
                color = mix(color, room, fresnel * 0.5);
            }

            vec3 mapped = vec3(1.0) - exp(-color * uExposure);
            fragColor = vec4(pow(mapped, vec3(1.0 / 2.2)), base.a);
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
