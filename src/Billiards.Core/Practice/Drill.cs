using System.Globalization;
using System.Text.Json;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Scenes;
using Billiards.Core.Table;

namespace Billiards.Core.Practice;

/// <summary>Where a drill wants the cue ball to stop: a disc on the bed.</summary>
/// <param name="Centre">The disc's centre on the bed (m; z is ignored).</param>
/// <param name="Radius">The disc's radius (m): the cue ball's centre must stop inside it.</param>
public sealed record DrillZone(Vec3 Centre, double Radius)
{
    /// <summary>The distance (m) in the bed plane from the zone's centre to <paramref name="p"/>.</summary>
    public double DistanceTo(Vec3 p) => (p - Centre).LengthXY;

    /// <summary>True when a ball centred at <paramref name="p"/> stopped in the zone.</summary>
    public bool Contains(Vec3 p) => DistanceTo(p) <= Radius;
}

/// <summary>
/// A drill (format <c>billiards-drill/1</c>, <c>assets/drills/NAME.json</c>): a position and a goal.
/// The goal pots the balls of <see cref="Sequence"/> in order, one a shot, each shot potting that
/// ball and no other and keeping the cue ball on the table; with a <see cref="Zone"/> the last shot
/// must also leave the cue ball in it; <see cref="Pockets"/> may name the pocket each ball must drop
/// in (a bank's). <see cref="Reference"/> holds shots that achieve it (one a
/// ball, played from where the previous left the balls): tests play them to prove every drill can
/// be done.
/// <code>
/// { "format": "billiards-drill/1", "title": "Stop shot", "goal": "Pot the 1; the cue ball stops dead.",
///   "scene": { "format": "billiards-scene/1", ... no shot ... },
///   "sequence": ["1"], "pockets": ["foot-left"], "zone": { "centre": [0.3, 0.0], "radius": 0.08 },
///   "reference": [ { "speed": 2.5, "aim_deg": 0.0, "tip": [0, -0.3], "elevation_deg": 0 } ] }
/// </code>
/// </summary>
/// <param name="Name">The drill's name: its file name without <c>.json</c> (<c>play --drill NAME</c>).</param>
/// <param name="Title">A short title for the menu and the HUD.</param>
/// <param name="Goal">One sentence saying what to do.</param>
/// <param name="Scene">The position (no shot), with a cue ball.</param>
/// <param name="Sequence">The balls to pot, in order (at least one).</param>
/// <param name="Zone">Where the last shot must leave the cue ball, or null.</param>
/// <param name="Reference">Shots that achieve the goal, one per ball of the sequence.</param>
public sealed record Drill(string Name, string Title, string Goal, Scene Scene, IReadOnlyList<BallId> Sequence, DrillZone? Zone, IReadOnlyList<ShotSpec> Reference)
{
    /// <summary>The pocket each ball of the sequence must drop in (<see cref="PocketId.None"/>: any), index-aligned with <see cref="Sequence"/>.</summary>
    public IReadOnlyList<PocketId> Pockets { get; init; } = [];

    /// <summary>
    /// A three-cushion drill (<c>"carom": true</c>, the carom balls): the goal is a point, the
    /// struck ball meeting both object balls with three cushions before the second
    /// (<see cref="Rules.ThreeCushionReferee.Read"/>), no ball leaving the table; the sequence names
    /// the two object balls in the order the pattern meets them, and one reference shot scores.
    /// </summary>
    public bool Carom { get; init; }

    /// <summary>The pocket the ball at <paramref name="index"/> of the sequence must drop in, or <see cref="PocketId.None"/> for any.</summary>
    public PocketId PocketFor(int index) => index < Pockets.Count ? Pockets[index] : PocketId.None;

    /// <summary>The format tag of a drill file.</summary>
    public const string Format = "billiards-drill/1";

    /// <summary>Parses a drill's JSON; <paramref name="path"/> names it in errors and gives its name.</summary>
    /// <exception cref="SceneException">When the text is malformed or the drill invalid.</exception>
    public static Drill Parse(string json, string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        using var doc = SceneLoader.ParseJson(json, path);
        var root = doc.RootElement;
        SceneException Bad(string at, string problem) => new(path, at, problem);
        if (root.ValueKind != JsonValueKind.Object)
        {
            throw Bad("$", "expected an object");
        }
        string[] allowed = ["format", "title", "goal", "scene", "sequence", "pockets", "zone", "reference", "carom"];
        foreach (var p in root.EnumerateObject())
        {
            if (!allowed.Contains(p.Name))
            {
                throw Bad("$." + p.Name, $"unknown field (expected one of {string.Join(", ", allowed)})");
            }
        }
        string Text(string field) => root.TryGetProperty(field, out var e) && e.ValueKind == JsonValueKind.String && e.GetString() is { Length: > 0 } s
            ? s
            : throw Bad("$." + field, "expected a non-empty string");
        if (Text("format") != Format)
        {
            throw Bad("$.format", $"expected \"{Format}\"");
        }
        if (!root.TryGetProperty("scene", out var sceneElement))
        {
            throw Bad("$.scene", "missing (the drill's position, a billiards-scene/1 object)");
        }
        var scene = SceneLoader.ReadScene(sceneElement, path + " (its scene)");
        if (scene.Shot is not null || scene.Game is not null || !scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            throw Bad("$.scene", "a drill's position has a cue ball, and no shot or game block");
        }
        if (!root.TryGetProperty("sequence", out var seq) || seq.ValueKind != JsonValueKind.Array || seq.GetArrayLength() == 0)
        {
            throw Bad("$.sequence", "expected an array of the balls to pot, in order");
        }
        var sequence = new List<BallId>();
        int i = 0;
        foreach (var item in seq.EnumerateArray())
        {
            // The scene's cue ball is struck; carom's other cue ball (the yellow) is an object ball here.
            if (item.ValueKind != JsonValueKind.String || !scene.BallSet.TryParse(item.GetString(), out var id) || id == scene.CueBall
                || !scene.Balls.Any(b => b.Id == id) || sequence.Contains(id))
            {
                throw Bad($"$.sequence[{i}]", "expected an object ball of the scene, once");
            }
            sequence.Add(id);
            i++;
        }
        bool carom = false;
        if (root.TryGetProperty("carom", out var caromElement))
        {
            carom = caromElement.ValueKind == JsonValueKind.True ? true
                : caromElement.ValueKind == JsonValueKind.False ? false
                : throw Bad("$.carom", "expected true or false");
            if (carom && (scene.BallSet != BallSet.Carom || sequence.Count != 2 || root.TryGetProperty("pockets", out _) || root.TryGetProperty("zone", out _)))
            {
                throw Bad("$.carom", "a carom drill has the carom balls, the two object balls as its sequence, and no pockets or zone");
            }
        }
        var pockets = new List<PocketId>();
        if (root.TryGetProperty("pockets", out var ps))
        {
            if (ps.ValueKind != JsonValueKind.Array || ps.GetArrayLength() != sequence.Count)
            {
                throw Bad("$.pockets", "expected one pocket (or null for any) per ball of the sequence");
            }
            int k = 0;
            foreach (var item in ps.EnumerateArray())
            {
                pockets.Add(item.ValueKind == JsonValueKind.Null ? PocketId.None
                    : item.ValueKind == JsonValueKind.String && scene.Table.Pockets.TryParse(item.GetString(), out var pocket) ? pocket
                    : throw Bad($"$.pockets[{k}]", $"expected a pocket of the table ({scene.Table.Pockets.Describe()}) or null"));
                k++;
            }
        }
        DrillZone? zone = null;
        if (root.TryGetProperty("zone", out var z))
        {
            if (z.ValueKind != JsonValueKind.Object || !z.TryGetProperty("centre", out var c) || c.ValueKind != JsonValueKind.Array || c.GetArrayLength() != 2
                || !z.TryGetProperty("radius", out var r) || r.ValueKind != JsonValueKind.Number || z.EnumerateObject().Count() != 2)
            {
                throw Bad("$.zone", "expected { \"centre\": [x, y], \"radius\": r } (m)");
            }
            double x = c[0].GetDouble(), y = c[1].GetDouble(), radius = r.GetDouble();
            if (!(radius > 0 && radius < 1) || Math.Abs(x) > scene.Table.HalfLength || Math.Abs(y) > scene.Table.HalfWidth)
            {
                throw Bad("$.zone", string.Create(CultureInfo.InvariantCulture, $"the zone must lie on the bed with a radius in (0, 1) m"));
            }
            zone = new DrillZone(new Vec3(x, y, 0), radius);
        }
        var reference = new List<ShotSpec>();
        if (root.TryGetProperty("reference", out var refs))
        {
            if (refs.ValueKind != JsonValueKind.Array || refs.GetArrayLength() != (carom ? 1 : sequence.Count))
            {
                throw Bad("$.reference", carom ? "expected one shot that scores the point" : "expected one shot per ball of the sequence");
            }
            int k = 0;
            foreach (var item in refs.EnumerateArray())
            {
                reference.Add(SceneLoader.ReadShot(item, path, $"$.reference[{k++}]"));
            }
        }
        string name = System.IO.Path.GetFileNameWithoutExtension(path);
        return new Drill(name, Text("title"), Text("goal"), scene, sequence, zone, reference) { Pockets = pockets, Carom = carom };
    }
}

/// <summary>How a drill's shot ended.</summary>
/// <param name="Potted">The object balls the shot pocketed, each with its pocket (<see cref="PocketId.None"/> for one sent off the table).</param>
/// <param name="CueOnTable">True when the cue ball stayed on the table.</param>
/// <param name="CueAtRest">Where the cue ball stopped (m).</param>
public sealed record DrillShot(IReadOnlyList<(BallId Ball, PocketId Pocket)> Potted, bool CueOnTable, Vec3 CueAtRest)
{
    /// <summary>What the struck ball met, read from the shot's events as three-cushion's referee reads them (a carom drill's goal).</summary>
    public Rules.ThreeCushionReferee.Contacts Contacts { get; init; }

    /// <summary>
    /// How a shot left a simulation at rest: the object balls out of play now that were on the table
    /// before (<paramref name="before"/>), the cue ball (<paramref name="cueBall"/>, else the set's
    /// cue ball: carom has two) and what it met.
    /// </summary>
    public static DrillShot Of(Physics.Simulation sim, IEnumerable<BallId> before, BallId? cueBall = null)
    {
        ArgumentNullException.ThrowIfNull(sim);
        var onTable = before.ToHashSet();
        var potted = new List<(BallId, PocketId)>();
        bool cueOn = false;
        var cueAt = Vec3.Zero;
        var balls = sim.Balls;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            var id = sim.Ids[i];
            if (cueBall is { } struck ? id == struck : sim.BallSet.IsCueBall(id))
            {
                cueOn = !balls[i].IsOutOfPlay;
                cueAt = balls[i].Position;
            }
            else if (balls[i].IsOutOfPlay && onTable.Contains(id))
            {
                potted.Add((id, balls[i].IsPocketed ? sim.Table.Pockets.Id(balls[i].Pocket) : PocketId.None));
            }
        }
        var cue = cueBall ?? sim.BallSet.CueBalls[0];
        return new DrillShot(potted, cueOn, cueAt) { Contacts = Rules.ThreeCushionReferee.Read(sim.Events.AsSpan(), cue) };
    }
}

/// <summary>The result of an attempt at a drill once it is over.</summary>
/// <param name="Success">True when the goal was met.</param>
/// <param name="Potted">How many balls of the sequence were potted in order.</param>
/// <param name="ZoneDistance">For a drill with a zone, on the last ball potted: the cue ball's distance from the zone's centre (m); else null.</param>
/// <param name="Reason">One sentence for the HUD.</param>
public sealed record DrillOutcome(bool Success, int Potted, double? ZoneDistance, string Reason);

/// <summary>
/// One attempt at a drill: the shots so far judged against its goal (a pure function of each shot's
/// result), until it succeeds or fails.
/// </summary>
public sealed class DrillAttempt(Drill drill)
{
    /// <summary>The drill.</summary>
    public Drill Drill { get; } = drill ?? throw new ArgumentNullException(nameof(drill));

    /// <summary>How many balls of the sequence have been potted.</summary>
    public int Potted { get; private set; }

    /// <summary>The ball to pot next, or null once the attempt is over.</summary>
    public BallId? Next => Outcome is null && Potted < Drill.Sequence.Count ? Drill.Sequence[Potted] : null;

    /// <summary>The result once the attempt is over, else null.</summary>
    public DrillOutcome? Outcome { get; private set; }

    /// <summary>Judges one shot; returns the outcome when it ends the attempt, else null (a sequence goes on).</summary>
    /// <exception cref="InvalidOperationException">When the attempt is already over.</exception>
    public DrillOutcome? Judge(DrillShot shot)
    {
        ArgumentNullException.ThrowIfNull(shot);
        if (Next is not { } next)
        {
            throw new InvalidOperationException("the attempt is over");
        }
        if (!shot.CueOnTable)
        {
            return End(false, null, "The cue ball left the table.");
        }
        if (Drill.Carom)
        {
            return JudgePoint(shot);
        }
        if (!shot.Potted.Any(p => p.Ball == next))
        {
            return End(false, null, $"The {next} was not potted.");
        }
        var wanted = Drill.PocketFor(Potted);
        if (wanted != PocketId.None && shot.Potted.First(p => p.Ball == next).Pocket != wanted)
        {
            return End(false, null, $"The {next} dropped, but not in the {wanted.ToName()} pocket.");
        }
        if (shot.Potted.Count > 1)
        {
            return End(false, null, $"Another ball dropped with the {next}.");
        }
        Potted++;
        if (Potted < Drill.Sequence.Count)
        {
            return null;
        }
        if (Drill.Zone is { } zone)
        {
            double d = zone.DistanceTo(shot.CueAtRest);
            return zone.Contains(shot.CueAtRest)
                ? End(true, d, string.Create(CultureInfo.InvariantCulture, $"The {next} went in and the cue ball stopped {d * 100:0.0} cm from the zone's centre."))
                : End(false, d, string.Create(CultureInfo.InvariantCulture, $"Potted, but the cue ball stopped {(d - zone.Radius) * 100:0.0} cm outside the zone."));
        }
        return End(true, null, Drill.Sequence.Count > 1 ? "Every ball potted in order." : $"The {next} went in.");
    }

    // A carom drill: one shot, a point or not (both balls count as made when it scores).
    private DrillOutcome JudgePoint(DrillShot shot)
    {
        var c = shot.Contacts;
        if (shot.Potted.Count > 0)
        {
            return End(false, null, $"The {shot.Potted[0].Ball} left the table.");
        }
        if (c.IsPoint)
        {
            Potted = Drill.Sequence.Count;
            return End(true, null, string.Create(CultureInfo.InvariantCulture, $"A point: both balls, {c.Cushions} cushions before the second."));
        }
        return End(false, null, c.FirstBall is null ? "No point: the cue ball met neither ball."
            : !c.BothBalls ? $"No point: the cue ball met only the {c.FirstBall}."
            : string.Create(CultureInfo.InvariantCulture, $"No point: {c.Cushions} cushion{(c.Cushions == 1 ? "" : "s")} before the second ball."));
    }

    private DrillOutcome End(bool success, double? distance, string reason) =>
        (Outcome = new DrillOutcome(success, Potted, distance, reason));
}
