using System.Globalization;
using System.Numerics;
using Billiards.App.Input;
using Billiards.App.Input.Modes;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Physics;

namespace Billiards.App.Game;

/// <summary>
/// The instant replay of the last shot (<see cref="ReplayKey"/>) and its tracking lines
/// (<see cref="TracksKey"/>). The replay is the shot itself played again from its snapshot at the
/// strike (Core's <see cref="ShotReplay"/>), not frames kept while it ran: at 1x, 1/2, 1/4 or 1/8
/// speed (1-4), paused (Space or P), scrubbed (Left/Right, Shift fine, held keys repeat), stepped to
/// the next or previous collision (N, Shift+N), seen from anywhere (view mode: drag orbits, the wheel
/// zooms, T the overhead view), left at any time (R or Escape). The table behind it does not
/// change: the game goes on from the shot's end. The tracking lines are each ball's path during
/// the last shot, drawn on the cloth with its collisions marked; shown (when on) after the shot
/// and during the replay, growing with the replay's time.
/// </summary>
public sealed class InstantReplayNode : Node, IShowsShot
{
    /// <summary>The key that starts the replay of the last shot, and leaves it.</summary>
    public const Key ReplayKey = Key.R;

    /// <summary>The key that shows or hides the tracking lines.</summary>
    public const Key TracksKey = Key.K;

    /// <summary>The key that steps to the next collision (with Shift, the previous one).</summary>
    public const Key EventKey = Key.N;

    /// <summary>The replay's speeds, keys 1 to 4 (1 real time).</summary>
    public static IReadOnlyList<double> Speeds { get; } = [1, 0.5, 0.25, 0.125];

    /// <summary>How far Left and Right scrub (s of the shot); Shift scrubs <see cref="FineScrubSeconds"/>.</summary>
    public const double ScrubSeconds = 0.1, FineScrubSeconds = 0.01;

    /// <summary>The lines are drawn this far above the bed (m): on the cloth, under the balls.</summary>
    public const float ClothLift = 0.002f;

    private PhysicsNode? _physics;
    private InputModeNode? _modes;
    private ShotReplay? _replay;
    private SimulationSnapshot? _replayOf;
    private Task<ShotReplay>? _pending;
    private SimulationSnapshot? _pendingOf;

    /// <summary>True while the replay is shown.</summary>
    public bool IsActive { get; private set; }

    /// <summary>True while the replay stands still (paused, or held at the shot's end).</summary>
    public bool IsPaused { get; private set; }

    /// <summary>The replay's speed (1 real time).</summary>
    public double Speed { get; private set; } = 1;

    /// <summary>The replay's time now (s after the strike), or 0 without one.</summary>
    public double Time => _replay?.Time ?? 0;

    /// <summary>The shot's length (s), or 0 without a replay.</summary>
    public double Duration => _replay?.Duration ?? 0;

    /// <summary>True while the tracking lines are shown.</summary>
    public bool ShowTracks { get; private set; }

    /// <summary>The replay shown, or the last shot's when the lines are on (null before the first shot).</summary>
    public ShotReplay? Replay => _replay;

    /// <inheritdoc />
    public ShotReplay? ShownShot => IsActive ? _replay : null;

    /// <inheritdoc />
    public ShotSpec? ShownStrike => IsActive ? _physics?.LastShot : null;

    /// <inheritdoc />
    public int ShownSeeks { get; private set; }

    /// <summary>Signal: the replay started (true) or ended (false).</summary>
    public event Action<bool>? ActiveChanged;

    /// <summary>The HUD's line while the replay is shown: its speed and time; else null.</summary>
    public string? Status => IsActive && _replay is { } r
        ? string.Create(CultureInfo.InvariantCulture, $"REPLAY {SpeedName(Speed)}  {r.Time:0.00} / {r.Duration:0.00} s{(IsPaused ? (r.Time >= r.Duration ? "  END" : "  PAUSED") : "")}")
        : null;

    /// <summary>The replay's keys, for the HUD while it is shown.</summary>
    public const string KeysLine = "Replay: 1-4 speed 1x 1/2 1/4 1/8, Space pause, Left/Right scrub, N next collision, K lines, R leaves.";

    /// <summary>A speed as the HUD writes it: 1x, 1/2x, 1/4x, 1/8x.</summary>
    public static string SpeedName(double speed) => speed >= 1
        ? string.Create(CultureInfo.InvariantCulture, $"{speed:0.##}x")
        : string.Create(CultureInfo.InvariantCulture, $"1/{1 / speed:0.##}x");

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _modes = FindInTree<InputModeNode>();
        _physics.Struck += _ => Forget();
        _physics.Undone += Forget;
        // The replay is made while the player looks at the table: R then starts it at once.
        _physics.CameToRest += _ => Prepare();
    }

    private void Forget()
    {
        Leave();
        _replay = null;
        _replayOf = null;
        _pending = null;
        _pendingOf = null;
    }

    // Starts making the last shot's replay on a background thread (from what the shot's
    // simulation is made of, read here, so that the game may go on with it meanwhile).
    private void Prepare()
    {
        if (_physics?.LastStrike is not { } strike || ReferenceEquals(_replayOf, strike.AtStrike) || ReferenceEquals(_pendingOf, strike.AtStrike))
        {
            return;
        }
        var sim = strike.Shot;
        var (model, ids, positions, rules, at, stepping) = (sim.TableModel, sim.Ids, ShotReplay.Positions(sim), sim.RefereeRules, strike.AtStrike, strike.Stepping);
        _pendingOf = at;
        _pending = BackgroundWork.Run(() => new ShotReplay(model, ids, positions, rules, at, Billiards.Core.Rules.Match.MaxShotTime, stepping));
    }

    /// <summary>
    /// Starts the replay of the last shot from its strike, at the current speed; false while balls
    /// roll or before any shot.
    /// </summary>
    public bool Start()
    {
        if (_physics is not { IsRolling: false } || Build(wait: true) is not { } replay)
        {
            return false;
        }
        replay.Seek(0);
        IsPaused = false;
        if (!IsActive)
        {
            IsActive = true;
            // The replay is watched, not played: view mode, so a drag turns the camera and never strikes.
            _modes?.TrySetMode(InputMode.View);
            ActiveChanged?.Invoke(true);
        }
        return true;
    }

    /// <summary>Leaves the replay: the table as the shot left it again.</summary>
    public void Leave()
    {
        if (!IsActive)
        {
            return;
        }
        IsActive = false;
        IsPaused = false;
        ActiveChanged?.Invoke(false);
    }

    /// <summary>Sets the replay's speed (one of <see cref="Speeds"/> from the keys; any positive rate here).</summary>
    public void SetSpeed(double speed)
    {
        if (double.IsFinite(speed) && speed > 0)
        {
            Speed = speed;
        }
    }

    /// <summary>Shows the replay at <paramref name="time"/> (s after the strike, clamped to the shot) and pauses it.</summary>
    public void SeekTo(double time)
    {
        if (_replay is { } r && IsActive)
        {
            r.Seek(time);
            ShownSeeks++;
            IsPaused = true;
        }
    }

    /// <summary>Pauses or resumes; resuming at the end starts from the strike again.</summary>
    public void TogglePause()
    {
        if (_replay is not { } r || !IsActive)
        {
            return;
        }
        if (IsPaused && r.Time >= r.Duration)
        {
            r.Seek(0);
        }
        IsPaused = !IsPaused;
    }

    // The last shot's replay, made once per shot (its first run gives the lines too); without
    // waiting, null while it is still being made.
    private ShotReplay? Build(bool wait)
    {
        if (_physics?.LastStrike is not { } strike)
        {
            return null;
        }
        if (_replay is not null && ReferenceEquals(_replayOf, strike.AtStrike))
        {
            return _replay;
        }
        Prepare();
        if (_pending is not { } pending || (!wait && !pending.IsCompleted))
        {
            return null;
        }
        _pending = null;
        _pendingOf = null;
        try
        {
            _replay = pending.GetAwaiter().GetResult();
            _replayOf = strike.AtStrike;
        }
        catch (Exception e) when (e is NotSupportedException or ArgumentException or InvalidOperationException)
        {
            _replay = null; // a simulation without snapshots has no replay
        }
        return _replay;
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (!IsActive || IsPaused || _replay is not { } r)
        {
            return;
        }
        r.Seek(r.Time + (dt * Speed));
        if (r.Time >= r.Duration)
        {
            IsPaused = true; // held at the end: Space plays it again, R leaves
        }
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is not KeyInput { Pressed: true } key)
        {
            // While the replay is shown the mouse only moves the camera (view mode).
            return false;
        }
        if (key.Key == TracksKey && !key.IsRepeat)
        {
            ShowTracks = !ShowTracks;
            return true;
        }
        if (!IsActive)
        {
            return key.Key == ReplayKey && !key.IsRepeat && Start();
        }
        var r = _replay!;
        switch (key.Key)
        {
            case ReplayKey or Key.Escape when !key.IsRepeat:
                Leave();
                return true;
            case Key.Space or Key.P when !key.IsRepeat:
                TogglePause();
                return true;
            case Key.Left or Key.Right:
                double step = key.Shift ? FineScrubSeconds : ScrubSeconds;
                SeekTo(r.Time + (key.Key == Key.Right ? step : -step));
                return true;
            case EventKey:
                if ((key.Shift ? r.PreviousEvent(r.Time) : r.NextEvent(r.Time)) is double at)
                {
                    SeekTo(at);
                }
                return true;
            case >= Key.D1 and <= Key.D4:
                Speed = Speeds[key.Key - Key.D1];
                return true;
            // The camera (T, the mouse), help, developer lines, sound and fullscreen work as ever;
            // keys that would aim, shoot, place or change the game wait until the replay ends.
            case Key.T or Key.H or Key.F1 or Key.F2 or Key.F3 or Key.F11 or Key.Plus or Key.Minus or Key.U or Key.V:
                return false;
            default:
                return true;
        }
    }

    /// <inheritdoc />
    protected override void Draw(FrameBuilder frame)
    {
        if (!IsActive || _replay is not { } r)
        {
            return;
        }
        // Drawn after the physics node: the replay's balls take the table's place.
        PhysicsNode.DrawInstead(frame, r);
    }

    /// <summary>
    /// The tracking lines for <paramref name="frame"/>'s camera (pixels): each ball's path on the
    /// cloth (up to the replay's time while it is shown, the whole shot after), a ring at each
    /// collision; none when the lines are off, balls roll, or no shot has been played.
    /// </summary>
    public IReadOnlyList<AidShape> Shapes(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        if (!ShowTracks || _physics is not { IsRolling: false } || (IsActive ? _replay : Build(wait: false)) is not { } r)
        {
            return [];
        }
        double until = IsActive ? r.Time : r.Duration;
        var vp = RenderMath.ViewProjection(frame);
        var shapes = new List<AidShape>(256);
        Vector2? Pixel(Core.Mathematics.Vec3 p) => RenderMath.ToPixel(vp, new Vector3((float)p.X, (float)p.Y, ClothLift), frame.Width, frame.Height);
        for (int i = 0; i < r.Ids.Count; i++)
        {
            var path = r.Paths[i];
            var colour = TrackColour(r.Ids[i]);
            Vector2? last = Pixel(path[0].Position);
            for (int p = 1; p < path.Count && path[p].Time <= until; p++)
            {
                var next = Pixel(path[p].Position);
                if (last is { } a && next is { } b && a != b)
                {
                    shapes.Add(new AidShape(a, b, 0, colour));
                }
                last = next;
            }
            if (IsActive && last is { } from && r.Current[i] is { IsOutOfPlay: false } ball && Pixel(ball.Position) is { } now && now != from)
            {
                // The line reaches the ball where the replay shows it.
                shapes.Add(new AidShape(from, now, 0, colour));
            }
        }
        var right = Vector3.Normalize(Vector3.Cross(frame.Target - frame.Eye, Vector3.UnitZ));
        float markRadius = (float)(0.45 * r.BallRadius);
        foreach (var mark in r.Marks)
        {
            if (mark.Time > until || mark.Kind == EventKind.BallPocket)
            {
                continue;
            }
            var centre = new Vector3((float)mark.Position.X, (float)mark.Position.Y, ClothLift);
            if (RenderMath.ToPixel(vp, centre, frame.Width, frame.Height) is { } c && RenderMath.ToPixel(vp, centre + (right * markRadius), frame.Width, frame.Height) is { } edge)
            {
                shapes.Add(new AidShape(c, c, MathF.Max(3, Vector2.Distance(c, edge)), mark.Kind == EventKind.BallBall ? BallMarkColour : CushionMarkColour));
            }
        }
        return shapes;
    }

    /// <summary>
    /// The tracking lines' cushion count on the carom table, for <paramref name="frame"/>'s camera
    /// (pixels): "1", "2", "3"... beside each cushion contact of the struck ball, in order, up to the
    /// replay's time while it is shown; none when the lines are off, balls roll, or off the carom table.
    /// </summary>
    public IReadOnlyList<HudLabel> Labels(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        if (!ShowTracks || _physics is not { IsRolling: false } physics || physics.Table.Preset != Core.Table.CaromTable.Preset
            || (IsActive ? _replay : Build(wait: false)) is not { StrikeEvent: { } strike } r)
        {
            return [];
        }
        double until = IsActive ? r.Time : r.Duration;
        var vp = RenderMath.ViewProjection(frame);
        var labels = new List<HudLabel>();
        int count = 0;
        foreach (var mark in r.Marks.Where(m => m.Kind == EventKind.BallCushion && m.Ball == strike.A).OrderBy(m => m.Time))
        {
            count++;
            if (mark.Time <= until && RenderMath.ToPixel(vp, new Vector3((float)mark.Position.X, (float)mark.Position.Y, ClothLift), frame.Width, frame.Height) is { } at)
            {
                labels.Add(new HudLabel(at.X + 6, at.Y - 20, count.ToString(CultureInfo.InvariantCulture), Gold: true));
            }
        }
        return labels;
    }

    private static readonly Vector4 BallMarkColour = new(1, 1, 1, 0.95f);
    private static readonly Vector4 CushionMarkColour = new(0.3f, 0.9f, 1f, 0.9f);

    // The balls' own colours (1-7 and 9-15 alike; the 8 a dark grey that shows on the cloth), the cue ball white.
    private static readonly Vector4[] BallColours =
    [
        new(0.97f, 0.97f, 0.95f, 0.9f),
        new(1f, 0.85f, 0.1f, 0.9f), new(0.25f, 0.45f, 1f, 0.9f), new(1f, 0.2f, 0.15f, 0.9f), new(0.7f, 0.35f, 0.95f, 0.9f),
        new(1f, 0.55f, 0.1f, 0.9f), new(0.2f, 0.85f, 0.35f, 0.9f), new(0.85f, 0.3f, 0.35f, 0.9f), new(0.25f, 0.25f, 0.25f, 0.9f),
    ];

    /// <summary>The colour of a ball's tracking line.</summary>
    public static Vector4 TrackColour(BallId ball)
    {
        int n = ball.Value;
        return BallSet.Pool.IsCueBall(ball) || n <= 0 ? BallColours[0] : BallColours[((n - 1) % 8) + 1];
    }
}
