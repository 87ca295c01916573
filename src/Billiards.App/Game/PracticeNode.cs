using System.Globalization;
using System.Numerics;
using Billiards.App.Camera;
using Billiards.App.Cli;
using Billiards.App.Input;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Practice;
using Billiards.App.Rendering;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Practice;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;
using Billiards.Core.Setup;

namespace Billiards.App.Game;

/// <summary>What practice starts with.</summary>
/// <param name="SavePath">Where the save key writes the position (and the load key reads it).</param>
/// <param name="Drill">The drill played, or null for free practice.</param>
/// <param name="Records">The drills' results kept between runs (a drill counts its attempts there), or null.</param>
/// <param name="Shot">A shot to set the cue to at the start (a saved position's), or null.</param>
public sealed record PracticeSetup(string SavePath, Drill? Drill = null, DrillRecords? Records = null, ShotSpec? Shot = null)
{
    /// <summary>The level whose error the sensitivity view samples at the start.</summary>
    public int SensitivityLevel { get; init; } = 3;
}

/// <summary>
/// Practice and drills (no referee). Free practice: drag any ball in move mode (M), add a ball under
/// the cursor (Insert) or remove the one under it (Delete), shoot from the keyboard (Space at the
/// power of W/Q, aim with Left/Right) or with the mouse, retry the last shot (Backspace: the balls,
/// aim, power, spin and elevation as they were), save the position with the cue's shot as a scene
/// (F5; <c>simulate</c> and <c>render</c> read it) and load it back (F9). A drill fixes the position and
/// judges every shot against its goal (<see cref="DrillAttempt"/>), draws its zone on the cloth,
/// shows the result and counts it in the records (Enter starts again). F6 shows the shot's
/// sensitivity: the planner's sampler (<see cref="ShotPlanner.Sensitivity"/>) plays the shot the
/// cue is set to with the error of a level (F7 cycles 1-5) and the HUD shows how often it pots,
/// with each sample's cue-ball ending drawn on the table (green where it potted, red where not) and,
/// for a miss, where the target ball stopped.
/// </summary>
/// <remarks>
/// Every shot goes through practice's <see cref="Session"/> (Core's turn controller without a referee) and
/// is struck on a new simulation of the position as a scene (the balls at rest, no
/// rack, the scene's physics), the scene the save key writes: <c>simulate</c> of a saved position
/// plays the window's shot bit for bit.
/// </remarks>
public sealed class PracticeNode(Scene start, PracticeSetup setup) : Node
{
    /// <summary>Keys of practice.</summary>
    public const Key RetryKey = Key.Backspace, SaveKey = Key.F5, LoadKey = Key.F9, AddKey = Key.Insert, RemoveKey = Key.Delete,
        SensitivityKey = Key.F6, LevelKey = Key.F7, AgainKey = Key.Enter;

    /// <summary>Samples of the sensitivity view.</summary>
    public const int SensitivitySamples = 40;

    /// <summary>The seed of the sensitivity view's error samples: the same shot, the same spread.</summary>
    public const ulong SensitivitySeed = 1;

    private static readonly Vector4 ZoneColour = new(1f, 0.85f, 0.2f, 0.9f);
    private static readonly Vector4 PottedColour = new(0.35f, 1f, 0.45f, 0.85f);
    private static readonly Vector4 MissedColour = new(1f, 0.35f, 0.3f, 0.85f);
    private static readonly Vector4 TargetColour = new(1f, 0.85f, 0.2f, 0.7f);

    private Scene _start = start with { Shot = null, Game = null };
    private PhysicsNode? _physics;
    private CameraNode? _camera;
    private CueNode? _cue;
    private InputModeNode? _modes;
    private ShotPlanner? _planner;
    private Scene? _before;
    private ShotSpec? _exact;
    private BallId? _dragging;
    private Matrix4x4 _viewProjection;
    private (int Width, int Height) _size;
    private Vector2 _cursor;
    private Task<ShotSensitivity>? _sampling;
    private (ShotSpec Shot, int Version)? _sampled;
    private (ShotSpec Shot, int Version)? _asked;
    private int _version;
    // The session's shot count when the drill's attempt under way struck its first shot.
    private int? _attemptStart;

    /// <summary>The drill played, or null in free practice.</summary>
    public Drill? Drill => setup.Drill;

    /// <summary>The attempt at the drill under way (or just ended), or null in free practice.</summary>
    public DrillAttempt? Attempt { get; private set; } = setup.Drill is { } d ? new DrillAttempt(d) : null;

    /// <summary>The drill's record after the last attempt counted, or the stored one.</summary>
    public DrillRecord? Record { get; private set; } = setup.Drill is { } d && setup.Records is { } r ? r[d.Name] : null;

    /// <summary>The keyboard power (m/s).</summary>
    public double Power { get; private set; } = 3.0;

    /// <summary>
    /// Practice's turn controller: the session of <see cref="PracticeRuleset"/> (no referee) that
    /// strikes every shot and keeps the timeline the retry and the take-back go back on.
    /// </summary>
    public Session? Session { get; private set; }

    /// <summary>The last shot struck, or null.</summary>
    public ShotSpec? LastShot { get; private set; }

    /// <summary>The position before the last shot (a scene without a shot), or null before the first.</summary>
    public Scene? Before => _before;

    /// <summary>The message shown now (saved, loaded, refused), or null.</summary>
    public string? Message { get; private set; }

    /// <summary>True while the sensitivity view is on.</summary>
    public bool ShowSensitivity { get; private set; }

    /// <summary>The level whose error the sensitivity view samples (1-5).</summary>
    public int SensitivityLevel { get; private set; } = Math.Clamp(setup.SensitivityLevel, SkillLevel.Min, SkillLevel.Max);

    /// <summary>The last sensitivity computed for the cue's shot of the moment, or null (off, sampling, or the shot changed).</summary>
    public ShotSensitivity? Sensitivity { get; private set; }

    /// <summary>True while the sensitivity view samples in the background.</summary>
    public bool IsSampling => _sampling is { IsCompleted: false };

    /// <summary>Signal: an attempt at the drill ended and was counted.</summary>
    public event Action<DrillOutcome>? AttemptEnded;

    /// <summary>The balls at rest now as a scene of the start's table and physics (no shot), sorted by id.</summary>
    public Scene Position() =>
        _start with { Path = "practice", Name = _start.Name ?? "Practice position", Rack = null, Balls = _physics!.BallsAtRest(), Shot = null, Rules = null };

    /// <summary>The shot the cue would play now: the restored one while nothing changed it, else the cue's at the keyboard power.</summary>
    public ShotSpec? CurrentShot()
    {
        if (_cue is null || _physics is not { IsRolling: false, HasCueBall: true })
        {
            return null;
        }
        var made = _cue.MakeShot(Power);
        return _exact is { } exact && Same(exact, made) ? exact : made;
    }

    // A restored shot goes through the camera's azimuth and the tip's centimetres: equal to the
    // last few bits. Any change by hand moves it by far more than this.
    private static bool Same(ShotSpec a, ShotSpec b) =>
        Math.Abs(Math.IEEERemainder(a.AimDeg - b.AimDeg, 360)) < 1e-6 && Math.Abs(a.Speed - b.Speed) < 1e-9
        && Math.Abs(a.TipSide - b.TipSide) < 1e-9 && Math.Abs(a.TipHeight - b.TipHeight) < 1e-9 && Math.Abs(a.ElevationDeg - b.ElevationDeg) < 1e-6;

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _camera = GetInTree<CameraNode>();
        _cue = FindInTree<CueNode>();
        _modes = FindInTree<InputModeNode>();
        // A drill's position is its own: the cue ball moves by hand only after a scratch.
        _physics.HandOnly = Drill is not null;
        _physics.StrikeThrough = OnStrike;
        _physics.CameToRest += _ => OnRest();
        Session = Session.Practice(Position(), _physics.CreateSimulation);
        if (setup.Shot is { } shot)
        {
            SetCue(shot);
        }
        else if (Drill is { } d && _camera is not null && _cue is not null)
        {
            // A drill starts aimed straight at its first ball.
            var target = d.Scene.Balls.First(b => b.Id == d.Sequence[0]).Position - _physics.CueBallPosition;
            CueAim.AimAt(_camera.Camera, _physics.CueBallPosition, DeterministicMath.Atan2(target.Y, target.X) * 180 / Math.PI);
        }
    }

    /// <summary>Back to the start: the drill's position (a new attempt) or the position practice began with.</summary>
    public void Restart()
    {
        if (_physics is null || _physics.IsRolling)
        {
            return;
        }
        _physics.Load(_physics.CreateSimulation(_start));
        _physics.EndBallInHand();
        if (Drill is { } d)
        {
            Attempt = new DrillAttempt(d);
        }
        Changed();
    }

    /// <summary>
    /// Retry: back on the session's timeline to the balls as they were before the last shot, and
    /// the cue set to it (aim, power, spin, elevation); false when there is no shot to retry or
    /// balls roll. It is practice's take-back too: pressed again, it goes back a shot further.
    /// </summary>
    public bool Retry()
    {
        if (_physics is null || _physics.IsRolling || Session is not { Game.Shots.Count: > 0 } session)
        {
            return false;
        }
        // A drill's attempt starts again from the drill's position with its first shot, whatever
        // shot it had reached: a sequence is judged from its first ball.
        int back = Drill is not null && _attemptStart is int first && first < session.Game.Shots.Count ? session.Game.Shots.Count - first : 1;
        var cue = session.Game.Shots[^back].Input.Shot;
        for (int i = 0; i < back; i++)
        {
            session.TakeBack();
        }
        if (Drill is { } d)
        {
            Attempt = new DrillAttempt(d);
            _attemptStart = null;
        }
        _physics.TakeBackTo(session.Game.Layout(), session.BallInHand != BallInHand.None);
        SetCue(cue);
        Say("Retry: the last shot's position and cue.");
        return true;
    }

    /// <summary>Strikes the cue's shot of the moment (<see cref="CurrentShot"/>).</summary>
    public void Shoot()
    {
        if (CurrentShot() is { } shot && Attempt is not { Outcome: not null })
        {
            _physics!.Strike(shot);
        }
    }

    // The cue set to a shot: aim, tip, elevation and power; kept exactly until something changes it.
    private void SetCue(ShotSpec shot)
    {
        if (_cue is null || _camera is null || _physics is null)
        {
            return;
        }
        CueAim.AimAt(_camera.Camera, _physics.CueBallPosition, shot.AimDeg);
        _cue.Take(shot);
        Power = shot.Speed;
        _exact = shot;
        Changed();
    }

    // Every strike goes through practice's session: from the balls as they lie now (moved by
    // hand or not), kept on the timeline, struck on a simulation of them as a scene.
    private Simulation? OnStrike(ShotSpec shot)
    {
        var position = Position();
        var session = Session!;
        if (Attempt is { Potted: 0, Outcome: null })
        {
            _attemptStart = session.Game.Shots.Count;
        }
        var sim = session.StrikeFrom(position, shot);
        if (sim is not null)
        {
            _before = position;
            LastShot = shot;
            Message = null;
        }
        return sim;
    }

    private void OnRest()
    {
        Changed();
        // No referee: the session notes the shot, and a cue ball that dropped comes back in hand.
        if (Session?.RestWithCueBallInHand(_physics!.Simulation) == true && Drill is null)
        {
            _physics.ReturnCueBall();
        }
        if (Attempt is not { Next: not null } attempt || _physics is null)
        {
            return;
        }
        var shot = DrillShot.Of(_physics.Simulation, _before?.Balls.Select(b => b.Id) ?? [], _physics.CueBall);
        if (attempt.Judge(shot) is { } outcome)
        {
            Record = setup.Records?.Record(attempt.Drill.Name, outcome, Console.Error) ?? (Record ?? DrillRecord.None).With(outcome);
            AttemptEnded?.Invoke(outcome);
        }
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (!ShowSensitivity || _physics is null)
        {
            return;
        }
        if (_sampling is { IsCompleted: true } done)
        {
            var (shot, version) = _asked!.Value;
            _sampling = null;
            if (done.IsCompletedSuccessfully)
            {
                Sensitivity = done.Result;
                _sampled = (shot, version);
            }
        }
        // One sampling at a time, for the shot of the moment; a shot changed meanwhile is sampled next.
        if (_sampling is null && CurrentShot() is { } now && (_sampled is not { } s || s.Version != _version || !Same(s.Shot, now)))
        {
            Sample(now);
        }
    }

    private void Sample(ShotSpec shot)
    {
        var physics = _physics!;
        _planner ??= new ShotPlanner(physics.Table, physics.Params, physics.Models);
        var planner = _planner;
        var position = TablePosition.Of(physics.Simulation, physics.CueBall);
        var level = SkillLevel.Of(SensitivityLevel);
        var target = Attempt?.Next ?? (FindInTree<AimLineNode>()?.Preview?.Ball);
        _asked = (shot, _version);
        if (_sampled is { } old && (old.Version != _version || !Same(old.Shot, shot)))
        {
            Sensitivity = null;
        }
        _sampling = BackgroundWork.Run(() => planner.Sensitivity(position, shot, level, SensitivitySamples, SensitivitySeed, target));
    }

    // The position or the level changed: a sensitivity shown is stale.
    private void Changed()
    {
        _version++;
        Sensitivity = null;
        _sampled = null;
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        switch (e)
        {
            case MouseMoveInput move:
                _cursor = move.Position;
                if (_dragging is { } id)
                {
                    Drag(id, move.Position);
                    return true;
                }
                return false;
            case MouseButtonInput { Button: MouseButton.Left, Pressed: true } down when _modes is { Mode: InputMode.Move } && CanEdit():
                _cursor = down.Position;
                _dragging = BallAt(down.Position);
                return _dragging is not null;
            case MouseButtonInput { Button: MouseButton.Left, Pressed: false } when _dragging is not null:
                _dragging = null;
                return true;
            case KeyInput { Pressed: true } key:
                return OnKey(key);
            default:
                return false;
        }
    }

    private bool OnKey(KeyInput key)
    {
        bool still = _physics is { IsRolling: false };
        switch (key.Key)
        {
            case Key.Space when still:
                Shoot();
                return true;
            case Key.W:
                Power = Math.Min(MatchNode.MaxPower, Power + MatchNode.PowerStep);
                return true;
            case Key.Q:
                Power = Math.Max(MatchNode.MinPower, Power - MatchNode.PowerStep);
                return true;
            case Key.Left or Key.Right or Key.A or Key.D when still && _camera is not null && _physics is not null:
                CueAim.Turn(_camera.Camera, _physics.CueBallPosition, key.Key switch
                {
                    Key.Left => key.Shift ? MatchNode.FineAimStepDegrees : MatchNode.AimStepDegrees,
                    Key.Right => key.Shift ? -MatchNode.FineAimStepDegrees : -MatchNode.AimStepDegrees,
                    Key.A => MatchNode.FineAimStepDegrees,
                    _ => -MatchNode.FineAimStepDegrees,
                });
                return true;
            case RetryKey:
                Retry();
                return true;
            case AgainKey when still:
                Restart();
                Say(Drill is null ? "Back to the start position." : "New attempt.");
                return true;
            case SaveKey when still:
                Save();
                return true;
            case LoadKey when still:
                Load();
                return true;
            case AddKey or Key.I when still:
                Add();
                return true;
            case RemoveKey when still:
                Remove();
                return true;
            case SensitivityKey:
                ShowSensitivity = !ShowSensitivity;
                if (!ShowSensitivity)
                {
                    Changed();
                }
                return true;
            case LevelKey:
                SensitivityLevel = SensitivityLevel % SkillLevel.Max + 1;
                Changed();
                return true;
            default:
                return false;
        }
    }

    private bool CanEdit() => Drill is null && _physics is { IsRolling: false };

    // The ball whose centre lies within a little more than its radius of the bed point under the pixel.
    private BallId? BallAt(Vector2 pixel)
    {
        if (_physics is null || Bed(pixel) is not { } p)
        {
            return null;
        }
        var sim = _physics.Simulation;
        BallId? best = null;
        double bestDistance = 1.3 * _physics.BallRadius;
        for (int i = 0; i < sim.Ids.Count; i++)
        {
            double d = (sim.Balls[i].Position - p).LengthXY;
            if (!sim.Balls[i].IsOutOfPlay && d < bestDistance)
            {
                (best, bestDistance) = (sim.Ids[i], d);
            }
        }
        return best;
    }

    private Vec3? Bed(Vector2 pixel)
    {
        if (_physics is null || _size.Width == 0)
        {
            return null;
        }
        double r = _physics.BallRadius;
        return RenderMath.ToPlane(_viewProjection, pixel, _size.Width, _size.Height, (float)r) is { } v
            ? new Vec3(v.X, v.Y, r)
            : null;
    }

    private void Drag(BallId id, Vector2 pixel)
    {
        if (_physics is not { IsRolling: false } physics || Bed(pixel) is not { } p)
        {
            return;
        }
        var clamped = CueBallMover.ClampToBed(p, physics.Table, physics.BallRadius);
        if (physics.Simulation.PlacementProblem(id, clamped) is null)
        {
            physics.Rearrange(sim => sim.PlaceBall(id, clamped));
            Changed();
        }
    }

    // The lowest-numbered ball of the set not on the table, under the cursor or else at the free spot nearest the foot spot.
    private void Add()
    {
        if (!CanEdit())
        {
            Say("A drill's position is fixed.");
            return;
        }
        var position = Position();
        var ids = position.Balls.Select(b => b.Id).ToHashSet();
        // The set's balls in order: the lowest-numbered object ball not on the table.
        BallId? next = null;
        foreach (var candidate in _start.BallSet.Ids)
        {
            if (next is null && !ids.Contains(candidate) && !_start.BallSet.IsCueBall(candidate))
            {
                next = candidate;
            }
        }
        if (next is not { } id)
        {
            Say("Every ball is on the table.");
            return;
        }
        double r = _physics!.BallRadius;
        var others = position.Balls.Select(b => (b.Id, b.Position)).ToList();
        var near = Bed(_cursor) is { } under && Placement.OnTable(_physics.Table, r, id, under) is null ? under : Initializer.FootSpot(_physics.Table, r);
        var spot = Placement.FreeSpotNear(_physics.Table, r, id, near, others);
        Rebuild(position with { Balls = [.. position.Balls, new BallSetup(id, spot, Vec3.Zero, Vec3.Zero)] });
        Say($"Added the {id}.");
    }

    private void Remove()
    {
        if (!CanEdit())
        {
            Say("A drill's position is fixed.");
            return;
        }
        if (BallAt(_cursor) is not { } id || id == _physics!.CueBall)
        {
            Say("Point at an object ball to remove it.");
            return;
        }
        var position = Position();
        Rebuild(position with { Balls = [.. position.Balls.Where(b => b.Id != id)] });
        Say($"Removed the {id}.");
    }

    private void Rebuild(Scene position)
    {
        var balls = position.Balls.OrderBy(b => b.Id.Value).ToList();
        _physics!.Load(_physics.CreateSimulation(position with { Balls = balls }));
        Changed();
    }

    /// <summary>Writes the position with the cue's shot to the save file (a billiards-scene/1 file).</summary>
    public void Save()
    {
        if (_physics is null || CurrentShot() is not { } shot)
        {
            return;
        }
        try
        {
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(setup.SavePath))!);
            OutputFiles.Write(setup.SavePath, SceneWriter.ToUtf8(Position() with { Shot = shot }));
            Say($"Saved the position and the shot to {setup.SavePath}.");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            Say($"Cannot save to {setup.SavePath}: {e.Message}");
        }
    }

    /// <summary>Loads the save file: its balls, and the cue set to its shot.</summary>
    public void Load()
    {
        if (_physics is null)
        {
            return;
        }
        if (Drill is not null)
        {
            Say("A drill's position is fixed.");
            return;
        }
        Scene scene;
        try
        {
            scene = SceneLoader.Load(setup.SavePath);
        }
        catch (SceneException e)
        {
            Say(e.Message);
            return;
        }
        if (scene.Table != _physics.Table || !scene.Balls.Any(b => b.Id == scene.CueBall))
        {
            Say($"{setup.SavePath} is for another table or has no cue ball: play --practice {setup.SavePath}");
            return;
        }
        _start = scene with { Shot = null, Game = null };
        Rebuild(_start);
        // A loaded position is a new session on its physics.
        Session = Session.Practice(Position(), _physics.CreateSimulation);
        if (scene.Shot is { } shot)
        {
            SetCue(shot);
        }
        Say($"Loaded {setup.SavePath}.");
    }

    private void Say(string message) => Message = message;

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        var f = frame.Frame;
        _viewProjection = RenderMath.ViewProjection(f);
        _size = (f.Width, f.Height);
        if (f.Hud is not { } hud)
        {
            return;
        }
        var aids = new List<AidShape>(hud.Aids ?? []);
        if (Drill?.Zone is { } zone)
        {
            Circle(aids, f, zone.Centre, zone.Radius, ZoneColour);
            Circle(aids, f, zone.Centre, zone.Radius * 0.96, ZoneColour);
        }
        if (ShowSensitivity && Sensitivity is { } s && _physics is { IsRolling: false } physics)
        {
            foreach (var ending in s.Endings)
            {
                if (ending.Cue is { } at)
                {
                    Circle(aids, f, at, physics.BallRadius * 0.5, ending.Potted ? PottedColour : MissedColour, 12);
                }
                // Where a miss left the target ball: a smaller ring of its own colour.
                if (ending.Target is { } target)
                {
                    Circle(aids, f, target, physics.BallRadius * 0.3, TargetColour, 8);
                }
            }
        }
        f.Hud = hud with { Lines = [.. hud.Lines, .. Lines()], Aids = aids };
    }

    /// <summary>The HUD's lines of practice: the drill and its result, the power, the sensitivity and the last message.</summary>
    public IReadOnlyList<string> Lines()
    {
        var c = CultureInfo.InvariantCulture;
        var lines = new List<string>();
        if (Drill is { } d)
        {
            lines.Add($"Drill: {d.Title}");
            lines.Add(d.Goal);
            if (Attempt is { } a)
            {
                lines.Add(a.Outcome is { } o
                    ? $"{(o.Success ? "SUCCESS" : "FAILED")}: {o.Reason} Enter: again, Backspace: retry the shot"
                    : d.Carom ? CaromGoal(d)
                    : d.Sequence.Count > 1 ? $"Next: the {a.Next} ({a.Potted + 1} of {d.Sequence.Count})" : $"Pot the {a.Next}");
            }
            if (Record is { } r)
            {
                string best = r.BestDistance is double b ? string.Create(c, $", best {b * 100:0.0} cm from the centre") : r.BestPotted > 0 && d.Sequence.Count > 1 ? $", best {r.BestPotted} of {d.Sequence.Count}" : "";
                lines.Add($"Attempts {r.Attempts}, successes {r.Successes}{best}");
            }
        }
        else
        {
            lines.Add("Practice: M then drag any ball; Insert adds, Delete removes; Backspace retries; F5 saves, F9 loads");
        }
        lines.Add(string.Create(c, $"Power {Power:0.00} m/s (W / Q), Space shoots; F6 sensitivity"));
        if (ShowSensitivity)
        {
            var level = SkillLevel.Of(SensitivityLevel);
            string error = string.Create(c, $"level {level.Level} (F7): aim {level.AimStdDeg:0.00} deg, speed {level.SpeedStdFraction * 100:0.#} %, tip {level.TipStdFraction:0.00} R");
            lines.Add(Sensitivity is { } s
                ? string.Create(c, $"Sensitivity, {error}: pots {s.Pots} of {s.Endings.Count} ({s.PotRate * 100:0} %)")
                : $"Sensitivity, {error}: sampling...");
        }
        if (Message is { } m)
        {
            lines.Add(m);
        }
        return lines;
    }

    // A circle on the bed as a ring of short lines, so that it lies on the cloth in perspective.
    private static void Circle(List<AidShape> aids, RenderFrame frame, Vec3 centre, double radius, Vector4 colour, int segments = 48)
    {
        var vp = RenderMath.ViewProjection(frame);
        Vector2? first = null, previous = null;
        for (int k = 0; k <= segments; k++)
        {
            double a = 2 * Math.PI * k / segments;
            var p = new Vector3((float)(centre.X + (radius * Math.Cos(a))), (float)(centre.Y + (radius * Math.Sin(a))), 0.001f);
            var pixel = RenderMath.ToPixel(vp, p, frame.Width, frame.Height);
            if (pixel is { } q && previous is { } r)
            {
                aids.Add(new AidShape(r, q, 0, colour));
            }
            previous = pixel;
            first ??= pixel;
        }
    }

    /// <summary>A carom drill's task in a line: the point, and the balls in the pattern's order.</summary>
    public static string CaromGoal(Drill drill)
    {
        ArgumentNullException.ThrowIfNull(drill);
        return $"Score: the {drill.Sequence[0]}, then the {drill.Sequence[1]} after three cushions";
    }
}
