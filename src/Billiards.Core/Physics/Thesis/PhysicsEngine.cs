using Billiards.Core.Mathematics;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Setup;

namespace Billiards.Core.Physics.Thesis;

/// <summary>How the last shot ended (seed 4.3.1).</summary>
public enum ShotEnd : byte
{
    /// <summary>No shot has ended yet, or one is under way.</summary>
    None,
    /// <summary>Every ball rests and no end-of-shot rule applied.</summary>
    Rested,
    /// <summary>The cue ball was pocketed and has been put back where the game started it.</summary>
    CueBallRespotted,
    /// <summary>The 8 ball was pocketed and the whole game has been reset.</summary>
    GameReset,
}

/// <summary>
/// The thesis model's physics (seed 4.1.4, 4.3): the seed's <c>calculatePhysics</c>, run at a
/// fixed step, in the seed's units (cm, cm/s, s) and frame (Y up, bed in the XZ plane).
/// </summary>
/// <remarks>
/// <para>Design. The seed's model is not a physical one: a ball has no spin, it moves in a
/// straight line and loses 0.35 % of its speed per 1/250 s; collisions are found by overlap
/// (ball-ball) or by the ball's centre crossing a triangle placed a radius in front of a cushion
/// (ball-rail), and resolved by swapping velocity components (ball-ball, times 0.95) or by
/// turning the velocity by a constructed rebound angle (ball-rail, times 0.9). The cue's tip
/// offset (e_x, e_y, kept on the <see cref="ThesisCue"/>, the thesis's <c>Queue</c>) bends the cue ball's first rebounds and
/// adds follow or draw at its ball contacts, and decays at each. Faithful means the same rules,
/// constants and order, in single precision like the seed: every step runs, ball after ball in
/// index order, the six steps of seed 4.3 on the state the earlier balls have already changed
/// (<see cref="CalculatePhysics"/>). Each listing is a method here so that tests can pin it.</para>
/// <para>Departures, each deliberate: (1) orientation (step 2) is only integrated when
/// <see cref="TrackOrientation"/> asks for it, for headless speed; it feeds nothing back into
/// the motion. (2) The damping factor per step is 0.9965^(250 dt) so that any dt damps per
/// second as the seed's 1/250 s does. (3) A ball that is dropping into a pocket takes no part in
/// ball-ball collisions: the seed is a game in the bed plane (4.3.5), and its 3D distance test
/// would tilt a bed ball's velocity out of that plane. (4) The acos of Formel 22 gets its
/// argument clamped to [-1, 1] so that rounding cannot make it NaN.</para>
/// <para>The shot ends (<see cref="CheckForRest"/>) when the summed speed of the balls in play falls
/// below <see cref="RestSpeed"/>; then the seed's end-of-shot rules apply: every velocity is set to
/// 0, a pocketed 8 ball resets the game, else a pocketed cue ball goes back to its start.
/// Events (ball-ball, ball-cushion, ball-pocket) go to <see cref="Events"/> when one is given,
/// stamped with the time at the end of the step that found them. Nothing allocates per step.</para>
/// </remarks>
/// <example>
/// The engine runs behind <see cref="Simulation"/> when a scene asks for the thesis model
/// (<c>"physics": {"model": "thesis"}</c>), like any other model:
/// <code language="csharp">
/// Scene scene = SceneLoader.Load("assets/scenes/thesis-eight-ball-break.json");
/// Simulation sim = SimulationRunner.Run(scene, new RunOptions()).Simulation;
/// Console.WriteLine($"{sim.Model}: {sim.Events.Count} events, at rest at {sim.Time:0.000} s");
/// </code>
/// </example>
public sealed partial class PhysicsEngine
{
    /// <summary>The seed's physics rate (steps per second, seed 4.1.4).</summary>
    public const float SeedStepsPerSecond = 250f;

    /// <summary>Ball radius r (cm).</summary>
    public const float BallRadius = 2.86f;

    /// <summary>Ball diameter 2r (cm), the ball-ball contact distance (seed 4.3.3).</summary>
    public const float BallDiameter = 5.72f;

    /// <summary>Damping of the speed per seed step of 1/250 s (Formel 5).</summary>
    public const float SeedDamping = 0.9965f;

    /// <summary>Speed kept by both balls in a ball-ball collision (Formel 16-17).</summary>
    public const float BallBallKeep = 0.95f;

    /// <summary>Speed kept at a cushion (Formel 29).</summary>
    public const float RailKeep = 0.9f;

    /// <summary>Speed divisor of the effet factor f = |v| / 4 (Formel 18), in cm/s.</summary>
    public const float EffetSpeedDivisor = 4f;

    /// <summary>Cap of the effet factor f (Formel 18).</summary>
    public const float EffetFactorCap = 100f;

    /// <summary>Degrees of rebound turn per cm of e_x per unit of f (Formel 24).</summary>
    public const float SideEffetScale = 0.3f;

    /// <summary>Largest rebound angle from the normal (deg, Listing 3).</summary>
    public const float MaxReboundDeg = 89f;

    /// <summary>Factor the effet keeps after each collision (seed 4.3.3, Listing 3).</summary>
    public const float EffetKeep = 0.2f;

    /// <summary>Factor on the horizontal speed at a non-bouncing pocket back wall (Listing 3).</summary>
    public const float BackWallKeep = 0.01f;

    /// <summary>Gravity as the seed writes it (cm/s^2): a pocketed ball falls at 981 * mass = 166.77 cm/s (Listing 4).</summary>
    public const float Gravity = 981f;

    /// <summary>Height (cm) below which a dropping ball is pocketed: out of play and no longer drawn (seed 4.3.5).</summary>
    public const float DropDepth = -20f;

    /// <summary>
    /// The shot ends when the summed speed of the balls in play falls below this (cm/s). The seed
    /// says "near 0, so that no motion is visible". Speeds decay as 0.9965^(250 t), a time
    /// constant of 1.14 s, so balls summing to 0.5 cm/s would roll 0.57 cm further in all: a fifth
    /// of a radius, below what the eye follows, and the threshold does not depend on dt.
    /// </summary>
    public const float RestSpeed = 0.5f;

    private readonly Ball[] _balls;
    private readonly CollisionGeometry[] _rails;
    private readonly RailCull _cull;

    // (1.001 D)^2: below it CalculateBallCollision decides, above it the balls are clearly apart.
    private const float ClearlyApartSquared = 1.002001f * BallDiameter * BallDiameter;
    private readonly Vector3[] _startPositions;
    private readonly Random _random;
    private readonly float _dt;
    private Vector3 _cueShotStart;

    /// <summary>Creates the engine for balls (in index order) on a table.</summary>
    /// <param name="balls">The balls; their current positions are where the game starts (for respot and reset).</param>
    /// <param name="rails">Collision triangles (<see cref="Initializer.InitRails"/>).</param>
    /// <param name="table">The table, for the pocket test.</param>
    /// <param name="queue">The cue, whose e_x and e_y are the cue ball's effet.</param>
    /// <param name="dt">Fixed step (s); the seed's is 1/250.</param>
    /// <param name="random">Source of orientations when the game is reset.</param>
    public PhysicsEngine(Ball[] balls, CollisionGeometry[] rails, ThesisTable table, ThesisCue queue, double dt, Random random)
        : this(balls, rails, new RailCull(rails), table, queue, dt, random)
    {
    }

    // The rails, their cull and the table are immutable: simulations of one table share them.
    internal PhysicsEngine(Ball[] balls, CollisionGeometry[] rails, RailCull cull, ThesisTable table, ThesisCue queue, double dt, Random random)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(dt);
        _balls = balls;
        _rails = rails;
        _cull = cull;
        Table = table;
        Queue = queue;
        Dt = dt;
        _dt = (float)dt;
        _random = random;
        // Formel 5 is per 1/250 s step: raise it to the number of seed steps in dt so that the
        // damping per second is the seed's, 0.9965^250 = 0.416, whatever the step.
        DampingPerStep = (float)DeterministicMath.Pow(SeedDamping, SeedStepsPerSecond * dt);
        _startPositions = new Vector3[balls.Length];
        for (int i = 0; i < balls.Length; i++)
        {
            _startPositions[i] = balls[i].Position;
            if (balls[i].IsCueBall)
            {
                _cueShotStart = balls[i].Position;
            }
        }
        IsAtRest = SummedSpeed() == 0;
    }

    /// <summary>The balls, in the order they are stepped.</summary>
    public IReadOnlyList<Ball> Balls => _balls;

    /// <summary>The collision triangles.</summary>
    public IReadOnlyList<CollisionGeometry> Rails => _rails;

    /// <summary>The table.</summary>
    public ThesisTable Table { get; }

    /// <summary>The cue, holding the cue ball's effet.</summary>
    public ThesisCue Queue { get; }

    /// <summary>Fixed step (s).</summary>
    public double Dt { get; }

    /// <summary>Speed factor per step, 0.9965^(250 dt).</summary>
    public float DampingPerStep { get; }

    /// <summary>Steps taken.</summary>
    public long Steps { get; private set; }

    /// <summary>Simulated time (s): <see cref="Steps"/> * <see cref="Dt"/>.</summary>
    public double Time => Steps * Dt;

    /// <summary>When true, step 2 (orientation, Listing 1) runs; it has no effect on the motion.</summary>
    public bool TrackOrientation { get; set; }

    /// <summary>True once the shot has ended (or before any ball moved).</summary>
    public bool IsAtRest { get; private set; }

    /// <summary>How the last shot ended.</summary>
    public ShotEnd LastShotEnd { get; private set; }

    /// <summary>
    /// When true (the default, the seed's behaviour) the end of a shot respots a pocketed cue ball
    /// and resets the game after the 8; a game whose referee rules sets it false, so that every
    /// ball stays where the shot left it and only the referee decides.
    /// </summary>
    public bool SeedEndOfShotRules { get; set; } = true;

    /// <summary>
    /// The cue ball's displacement over the last shot (cm), from where it was struck to where it
    /// lies after the end-of-shot rules: the seed moves its camera by this (seed 4.3.1).
    /// </summary>
    public Vector3 LastCueDisplacement { get; private set; }

    /// <summary>Where the events go; none are logged when null.</summary>
    public EventLog? Events { get; set; }

    /// <summary>
    /// Puts every ball back where the engine started, with the given velocities (cm/s), and the
    /// clock at 0. Unlike <see cref="Initializer.ResetGame"/> it keeps the orientations and draws no
    /// random numbers, so a rerun repeats bit for bit; it allocates nothing.
    /// </summary>
    public void Restart(ReadOnlySpan<Vector3> velocities)
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            var ball = _balls[i];
            ball.Position = _startPositions[i];
            ball.Velocity = velocities[i];
            ball.Pocket = -1;
            ball.IsPocketed = false;
            if (ball.IsCueBall)
            {
                _cueShotStart = ball.Position;
            }
        }
        Queue.Reset();
        Steps = 0;
        LastShotEnd = ShotEnd.None;
        LastCueDisplacement = Vector3.Zero;
        IsAtRest = SummedSpeed() == 0;
    }

    /// <summary>Strikes: gives the cue ball (number 0) a velocity (cm/s) and starts a shot.</summary>
    public void Shoot(Vector3 velocity)
    {
        foreach (var ball in _balls)
        {
            if (ball.IsCueBall)
            {
                ball.Velocity = velocity;
                _cueShotStart = ball.Position;
            }
        }
        IsAtRest = SummedSpeed() == 0;
        LastShotEnd = ShotEnd.None;
    }

    /// <summary>
    /// One step of <see cref="Dt"/> (the seed calls <c>calculatePhysics</c> 250 times per simulated
    /// second). For every ball in index order: 1 new position, 2 new orientation, 3 rail
    /// collision, 4 pocket test, 5 collision with every other ball, 6 new velocity; then the stop
    /// rule. Does nothing once the shot has ended.
    /// </summary>
    public void CalculatePhysics()
    {
        if (IsAtRest)
        {
            return;
        }
        Steps++;
        for (int i = 0; i < _balls.Length; i++)
        {
            var ball = _balls[i];
            if (ball.IsPocketed)
            {
                continue;
            }
            var oldPosition = ball.Position;
            ball.Position = oldPosition + ball.Velocity * _dt;                           // 1
            if (TrackOrientation)
            {
                ball.Orientation = Roll(ball.Orientation, ball.Position - oldPosition);   // 2
            }
            CalculateRailCollision(ball);                                                // 3
            CheckForPockets(ball);                                                       // 4
            if (ball.IsOnBed)                                                            // 5
            {
                for (int j = 0; j < _balls.Length; j++)
                {
                    // Balls clearly apart (squared distance beyond D^2 by far more than round-off)
                    // cannot collide: skip the call and its square root; the result is the same.
                    if (j != i && _balls[j].IsOnBed && Vector3.DistanceSquared(_balls[j].Position, ball.Position) < ClearlyApartSquared)
                    {
                        CalculateBallCollision(ball, _balls[j]);
                    }
                }
            }
            ball.Velocity *= DampingPerStep;                                             // 6
            if (ball.Pocket >= 0 && ball.Position.Y < DropDepth)
            {
                ball.IsPocketed = true;
                ball.Velocity = Vector3.Zero;
            }
        }
        CheckForRest();
    }

    /// <summary>
    /// Formel 6-10 and Listing 1: the orientation after the ball's centre moved by
    /// <paramref name="displacement"/> (cm), rolling: axis a = normalize((0,1,0) x d), angle
    /// |d| / 2.86, q = (cos(angle/2), sin(angle/2) a), new orientation q * old (Formel 10, q first in
    /// the product, so the step's turn is applied after the old orientation). Moves under 1e-6 cm
    /// leave it as it is.
    /// </summary>
    public static Quaternion Roll(Quaternion orientation, Vector3 displacement)
    {
        float distance = displacement.Length();
        if (distance <= 0.000001f)
        {
            return orientation;
        }
        var axis = Vector3.Normalize(Vector3.Cross(Vector3.UnitY, displacement));
        float angle = distance / BallRadius;
        var step = new Quaternion((float)DeterministicMath.Sin(angle / 2) * axis, (float)DeterministicMath.Cos(angle / 2));
        return step * orientation; // System.Numerics' * is the Hamilton product of Formel 10
    }

    /// <summary>
    /// Formel 11-19 (seed 4.3.3): if the balls overlap (|p2 - p1| &lt; 5.72), puts
    /// <paramref name="first"/> back to touching (Formel 11), splits both velocities along
    /// d_n = normalize(p2 - p1) and n = normalize((0,1,0) x d) (12-15), swaps the d_n parts and keeps
    /// 0.95 (16-17); the cue ball then gets follow or draw (18-19) and its e_y decays.
    /// </summary>
    /// <returns>True when the balls collided.</returns>
    public bool CalculateBallCollision(Ball first, Ball second)
    {
        var d = second.Position - first.Position;
        float distance = d.Length();
        // Balls on one spot have no line of centres; the seed would divide by zero.
        if (distance >= BallDiameter || distance == 0)
        {
            return false;
        }
        var dn = d / distance;
        first.Position = second.Position - dn * BallDiameter;                            // 11
        var n = Vector3.Normalize(Vector3.Cross(Vector3.UnitY, d));
        var v1 = first.Velocity;
        var v2 = second.Velocity;
        float vd1 = Vector3.Dot(v1, dn), vn1 = Vector3.Dot(v1, n);                       // 12, 13
        float vd2 = Vector3.Dot(v2, dn), vn2 = Vector3.Dot(v2, n);                       // 14, 15
        var after1 = (vd2 * dn + vn1 * n) * BallBallKeep;                                // 16
        var after2 = (vd1 * dn + vn2 * n) * BallBallKeep;                                // 17
        if (first.IsCueBall)
        {
            after1 = FollowOrDraw(after1, v1);
        }
        else if (second.IsCueBall)
        {
            after2 = FollowOrDraw(after2, v2);
        }
        first.Velocity = after1;
        second.Velocity = after2;
        Log(EventKind.BallBall, first, second, -1, MathF.Max(0, vd1 - vd2));
        return true;
    }

    /// <summary>
    /// Formel 18-19: v_e = v' + v_old / |v_old| * e_y * f with f = |v_old| / 4 capped at 100; then
    /// e_y *= 0.2, and a negative e_y (draw) is inverted so that it turns to follow after the first
    /// contact (seed 4.3.3).
    /// </summary>
    /// <remarks>
    /// f is taken from the cue ball's speed before the collision, v_old: the seed wants "a harder
    /// shot gives more effet", and after a full hit the cue ball's new speed is about 0, which
    /// would take all follow and draw away from the straight shot they are made for. A cue ball
    /// at rest when hit has no direction to add effet along; it gets none, but e_y still decays.
    /// </remarks>
    /// <param name="after">The cue ball's velocity from Formel 16 or 17 (cm/s).</param>
    /// <param name="before">The cue ball's velocity before the collision (cm/s).</param>
    /// <returns>The velocity with follow or draw (cm/s).</returns>
    public Vector3 FollowOrDraw(Vector3 after, Vector3 before)
    {
        float speed = before.Length();
        if (speed > 0)
        {
            float f = MathF.Min(speed / EffetSpeedDivisor, EffetFactorCap);
            after += before / speed * (Queue.EY * f);
        }
        Queue.EY = MathF.Abs(Queue.EY * EffetKeep);
        return after;
    }

    /// <summary>
    /// Step 3 (seed 4.3.4, Listings 2-3): finds the triangle whose crossing with the ball's line of
    /// motion is nearest to the ball, and if the ball's centre is on or behind it
    /// (dot(n, p - p1) &lt;= 0), turns the velocity (<see cref="Rebound"/>) and puts the ball on the
    /// crossing.
    /// </summary>
    /// <returns>The triangle the ball rebounded from, or -1.</returns>
    public int CalculateRailCollision(Ball ball)
    {
        int nearest = FindNearestHit(_rails, _cull, ball.Position, ball.Velocity, out var point);
        if (nearest < 0)
        {
            return -1;
        }
        var rail = _rails[nearest];
        if (Vector3.Dot(rail.Normal, ball.Position - rail.P1) > 0)
        {
            return -1;
        }
        float approach = -Vector3.Dot(ball.Velocity, rail.Normal);
        ball.Velocity = Rebound(ball.Velocity, rail.Normal, rail.IsBouncing, ball.IsCueBall ? Queue : null);
        ball.Position = point;
        Log(EventKind.BallCushion, ball, ball, rail.Feature, MathF.Max(0, approach));
        return nearest;
    }

    /// <summary>
    /// Listing 2 over all triangles: the index of the triangle whose crossing with the line
    /// position + t * velocity is nearest to <paramref name="position"/> (either side of it), and
    /// the crossing; -1 when the line crosses none. Ties keep the first.
    /// </summary>
    public static int FindNearestHit(ReadOnlySpan<CollisionGeometry> rails, Vector3 position, Vector3 velocity, out Vector3 point) =>
        FindNearestHit(rails, null, position, velocity, out point);

    // The same, skipping (eight at a time) the triangles whose footprint on the bed lies clearly on
    // one side of a level line: a speed-up only. A skipped triangle is one the ray test would miss
    // too (the margin, 1e-4 of the table's extent, is far above float round-off), and the rest are
    // tested in index order, so the result is the same bit for bit. Without a cull nothing is skipped.
    private static int FindNearestHit(ReadOnlySpan<CollisionGeometry> rails, RailCull? cull,
        Vector3 position, Vector3 velocity, out Vector3 point)
    {
        point = position;
        if (velocity == Vector3.Zero)
        {
            return -1; // every triangle would report Parallel
        }
        int nearest = -1;
        float nearestDistance = float.MaxValue;
        if (cull is null || cull.Count != rails.Length || velocity.Y != 0)
        {
            for (int k = 0; k < rails.Length; k++)
            {
                Consider(rails[k], k, position, velocity, ref nearest, ref nearestDistance, ref point);
            }
            return nearest;
        }
        float margin = 1e-4f * (MathF.Abs(velocity.X) + MathF.Abs(velocity.Z)) * (cull.Extent + MathF.Abs(position.X) + MathF.Abs(position.Z));
        var px = Vector256.Create(position.X);
        var pz = Vector256.Create(position.Z);
        var vx = Vector256.Create(velocity.X);
        var vz = Vector256.Create(velocity.Z);
        var above = Vector256.Create(margin);
        var below = Vector256.Create(-margin);
        for (int k = 0; k < rails.Length; k += RailCull.Lanes)
        {
            uint near = cull.Near(k, px, pz, vx, vz, above, below);
            while (near != 0)
            {
                int index = k + BitOperations.TrailingZeroCount(near);
                near &= near - 1;
                if (index >= rails.Length)
                {
                    break;
                }
                Consider(rails[index], index, position, velocity, ref nearest, ref nearestDistance, ref point);
            }
        }
        return nearest;
    }

    // Listing 2's test of one triangle; keeps the nearest crossing (ties keep the first).
    private static void Consider(CollisionGeometry rail, int k, Vector3 position, Vector3 velocity,
        ref int nearest, ref float nearestDistance, ref Vector3 point)
    {
        if (rail.Intersect(position, velocity, out _, out var hit) == RayHit.Hit)
        {
            float distance = (hit - position).Length();
            if (distance < nearestDistance)
            {
                nearestDistance = distance;
                nearest = k;
                point = hit;
            }
        }
    }

    /// <summary>
    /// Formel 22-29 as Listing 3 writes them: the rebound velocity (cm/s) of a ball with
    /// <paramref name="velocity"/> (cm/s) at a triangle with unit <paramref name="normal"/>.
    /// </summary>
    /// <remarks>
    /// alpha = acos(-v.n / |v|) in degrees; c = v x n; for the cue ball (when
    /// <paramref name="cueEffet"/> is given) alpha -= e_x 0.3 f if c.y &gt; 0, else alpha += e_x 0.3 f,
    /// f = |v| / 4 capped at 100; h = n x (0,1,0) if c.y &gt; 0, else (0,1,0) x n. alpha is capped
    /// at 89 from above only, as in the listing (a large opposite e_x may make it negative: the
    /// ball then comes off on the other side of the normal). The new direction normalize(n +
    /// normalize(h) tan alpha), horizontal parts times 0.01 at a non-bouncing wall, times
    /// 0.9 |v|. The cue ball's e_x then keeps 0.2 and e_y turns by -0.2. The seed's text
    /// (Formel 23) tests v x (0,1,0) instead; the listing wins. With e_x = 0 this is the mirror
    /// reflection of Formel 21, times 0.9.
    /// </remarks>
    public static Vector3 Rebound(Vector3 velocity, Vector3 normal, bool isBouncing, ThesisCue? cueEffet)
    {
        float speed = velocity.Length();
        float cosine = Vector3.Dot(-velocity, normal) / (speed * normal.Length());
        float angle = (float)DeterministicMath.Acos(Math.Clamp(cosine, -1f, 1f)) * 180f / MathF.PI;          // 22
        var vCrossN = Vector3.Cross(velocity, normal);                                     // 23
        float f = MathF.Min(speed / EffetSpeedDivisor, EffetFactorCap);
        Vector3 h;
        if (vCrossN.Y > 0)
        {
            if (cueEffet is not null)
            {
                angle -= cueEffet.EX * SideEffetScale * f;                                 // 24
            }
            h = Vector3.Cross(normal, Vector3.UnitY);                                      // 25
        }
        else
        {
            if (cueEffet is not null)
            {
                angle += cueEffet.EX * SideEffetScale * f;                                 // 24
            }
            h = Vector3.Cross(Vector3.UnitY, normal);                                      // 26
        }
        angle = MathF.Min(angle, MaxReboundDeg);
        if (cueEffet is not null)
        {
            cueEffet.EX *= EffetKeep;
        }
        float l = (float)DeterministicMath.Tan(angle * MathF.PI / 180f);                                     // 27
        var direction = Vector3.Normalize(normal + Vector3.Normalize(h) * l);             // 28
        if (!isBouncing)
        {
            direction.X *= BackWallKeep;
            direction.Z *= BackWallKeep;
        }
        direction *= speed * RailKeep;                                                     // 29
        if (cueEffet is not null)
        {
            cueEffet.EY *= -EffetKeep;
        }
        return direction;
    }

    /// <summary>
    /// Step 4 (Formel 30, Listing 4): a ball within a pocket's test circle falls, its vertical
    /// velocity set to -981 * mass every step it is there; the first time, the ball is marked with
    /// the pocket and a pocket event is logged.
    /// </summary>
    /// <returns>The pocket index, or -1.</returns>
    public int CheckForPockets(Ball ball)
    {
        int pocket = Table.PocketAt(ball.Position);
        if (pocket < 0)
        {
            return -1;
        }
        // The speed it drops with is its speed on the bed as the pocket test catches it.
        float dropSpeed = ball.Velocity.Length();
        ball.Velocity = ball.Velocity with { Y = -Gravity * Ball.Mass };
        if (ball.Pocket < 0)
        {
            ball.Pocket = pocket;
            Log(EventKind.BallPocket, ball, ball, pocket, dropSpeed);
        }
        return pocket;
    }

    /// <summary>
    /// The stop rule (seed 4.3.1): when the summed speed of the balls in play is below
    /// <see cref="RestSpeed"/>, ends the shot: every velocity to 0; if the 8 ball was pocketed, the
    /// whole game is reset (<see cref="Initializer.ResetGame"/>); else if the cue ball was, it goes
    /// back to its start; the cue is reset.
    /// </summary>
    /// <remarks>
    /// A headless run applies these rules like the game does, so its final state is the table
    /// the next shot is played on; the event log still shows every drop. The 8 ball resets the
    /// game whatever the rack (the seed has no game rules). The respot ignores any ball lying on
    /// the start spot, as the seed does.
    /// </remarks>
    /// <returns>True when the shot ended.</returns>
    public bool CheckForRest()
    {
        if (SummedSpeed() >= RestSpeed)
        {
            return false;
        }
        foreach (var ball in _balls)
        {
            ball.Velocity = Vector3.Zero;
        }
        int cue = -1, eight = -1;
        for (int i = 0; i < _balls.Length; i++)
        {
            if (_balls[i].IsCueBall)
            {
                cue = i;
            }
            else if (_balls[i].Number == 8)
            {
                eight = i;
            }
        }
        if (!SeedEndOfShotRules)
        {
            LastShotEnd = ShotEnd.Rested;
        }
        else if (eight >= 0 && _balls[eight].IsPocketed)
        {
            Initializer.ResetGame(_balls, _startPositions, Queue, _random);
            LastShotEnd = ShotEnd.GameReset;
        }
        else if (cue >= 0 && _balls[cue].IsPocketed)
        {
            _balls[cue].Position = FreeSpotNear(cue, _startPositions[cue]);
            _balls[cue].Pocket = -1;
            _balls[cue].IsPocketed = false;
            LastShotEnd = ShotEnd.CueBallRespotted;
        }
        else
        {
            LastShotEnd = ShotEnd.Rested;
        }
        Queue.Reset();
        LastCueDisplacement = cue >= 0 ? _balls[cue].Position - _cueShotStart : Vector3.Zero;
        IsAtRest = true;
        return true;
    }

    // Step (cm) of the rings FreeSpotNear searches, and their number of points.
    private const float RespotStep = 0.1f;
    private const int RespotPoints = 72;

    /// <summary>
    /// Where ball <paramref name="index"/> goes back to: <paramref name="start"/> when no ball on
    /// the bed lies within a diameter of it, else the nearest free point on the bed around it, to
    /// within <see cref="RespotStep"/> (rings of growing radius, each walked from the head side).
    /// The seed put the cue ball back on its start even onto a ball lying there, which left the two
    /// overlapping at rest.
    /// </summary>
    private Vector3 FreeSpotNear(int index, Vector3 start)
    {
        if (IsFree(index, start))
        {
            return start;
        }
        float maxRadius = 2 * (Table.HalfLength + Table.HalfWidth);
        for (float radius = RespotStep; radius < maxRadius; radius += RespotStep)
        {
            for (int k = 0; k < RespotPoints; k++)
            {
                double angle = Math.PI + 2 * Math.PI * k / RespotPoints;
                var p = new Vector3(start.X + radius * (float)DeterministicMath.Cos(angle), start.Y, start.Z + radius * (float)DeterministicMath.Sin(angle));
                if (IsFree(index, p))
                {
                    return p;
                }
            }
        }
        return start; // a full table: nothing better exists
    }

    // On the bed, R inside the cushion noses, and clear of every other ball on it (with a margin
    // well above single precision's round-off).
    private bool IsFree(int index, Vector3 p)
    {
        if (Math.Abs(p.X) > Table.HalfLength - BallRadius || Math.Abs(p.Z) > Table.HalfWidth - BallRadius)
        {
            return false;
        }
        const float clear = (BallDiameter + 0.01f) * (BallDiameter + 0.01f);
        for (int j = 0; j < _balls.Length; j++)
        {
            if (j != index && _balls[j].IsOnBed && Vector3.DistanceSquared(_balls[j].Position, p) < clear)
            {
                return false;
            }
        }
        return true;
    }

    private float SummedSpeed()
    {
        float sum = 0;
        foreach (var ball in _balls)
        {
            if (!ball.IsPocketed)
            {
                sum += ball.Velocity.Length();
            }
        }
        return sum;
    }

    private void Log(EventKind kind, Ball a, Ball b, int feature, float approachCmPerS)
    {
        Events?.Add(new SimEvent(Time, kind, new BallId(a.Number), new BallId(b.Number), feature, approachCmPerS / 100.0));
    }
}
