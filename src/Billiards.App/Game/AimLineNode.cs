using System.Numerics;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The aim line (<see cref="AimPreview"/>): the cue ball's path to the first ball it meets, the
/// ghost ball there, and the object ball's direction after contact, stopped at the cushion; with
/// no ball on the line, the path to the cushion and its bank off it. Nothing is drawn over the
/// rails or the floor. Drawn as a few flat shapes over the view (<see cref="AidShape"/>): three thin quads
/// and a ring, so it costs a software rasteriser almost nothing. <see cref="ToggleKey"/> turns it
/// on and off; it starts on for practice and against a computer of level 2 or less.
/// </summary>
public sealed class AimLineNode : Node
{
    /// <summary>The key that shows or hides the aim line.</summary>
    public const Key ToggleKey = Key.L;

    /// <summary>How far the object ball's direction is drawn at most (m): less when it reaches a cushion first.</summary>
    public const double ObjectLineLength = 0.5;

    /// <summary>The highest computer level against which the line starts on.</summary>
    public const int HelpedAgainstLevel = 2;

    private static readonly Vector4 PathColour = new(1, 1, 1, 0.7f);
    private static readonly Vector4 GhostColour = new(1, 1, 1, 0.8f);
    private static readonly Vector4 ObjectColour = new(1, 0.85f, 0.2f, 0.85f);
    private static readonly Vector4 BankColour = new(1, 1, 1, 0.4f);

    private PhysicsNode? _physics;
    private CueNode? _cue;
    private MatchNode? _match;
    private PocketCircle[] _pockets = [];

    /// <summary>True while the line is shown.</summary>
    public bool Visible { get; private set; }

    /// <summary>The preview drawn in the last frame, or null.</summary>
    public AimPreview? Preview { get; private set; }

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _cue = FindInTree<CueNode>();
        _match = FindInTree<MatchNode>();
        _pockets = TableGeometry.Build(_physics.Table, _physics.BallRadius).Pockets.ToArray();
        Visible = _match is null || _match.Session.Seats.Any(p => p.ComputerLevel is <= HelpedAgainstLevel);
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is KeyInput { Pressed: true, Key: ToggleKey })
        {
            Visible = !Visible;
            return true;
        }
        return false;
    }

    /// <summary>
    /// The shapes to draw for <paramref name="frame"/>'s camera (pixels), or none when the line is
    /// off, the balls roll, or there is no cue ball.
    /// </summary>
    public IReadOnlyList<AidShape> Shapes(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        Preview = null;
        if (!Visible || _cue is not { IsVisible: true } cue || _physics is not { } physics)
        {
            return [];
        }
        var sim = physics.Simulation;
        int cueIndex = sim.IndexOf(physics.CueBall);
        var preview = AimPreview.Compute(sim.Balls, sim.Ids, cueIndex, cue.AimDirection, physics.BallRadius, _pockets, physics.Table.Pockets, physics.Table);
        Preview = preview;
        float r = (float)physics.BallRadius;
        var lift = new Vector3(0, 0, r);
        var vp = RenderMath.ViewProjection(frame);
        // From the cue ball's front, not over the ball itself.
        var start = ((physics.CueBallPosition with { Z = 0 }) + (physics.BallRadius * cue.AimDirection)).ToVector3() + lift;
        var ghost = preview.Ghost.ToVector3() + lift;
        var shapes = new List<AidShape>(3);
        if (Segment(vp, frame, start, ghost, PathColour) is { } path)
        {
            shapes.Add(path);
        }
        if (preview.Bank is { } bank && Segment(vp, frame, ghost, bank.ToVector3() + lift, BankColour) is { } banked)
        {
            shapes.Add(banked);
        }
        if (preview.Ball is { } ball && RenderMath.ToPixel(vp, ghost, frame.Width, frame.Height) is { } g)
        {
            // The ring's radius on screen: the ball's radius seen at the ghost ball's distance.
            var right = Vector3.Normalize(Vector3.Cross(frame.Target - frame.Eye, Vector3.UnitZ));
            if (RenderMath.ToPixel(vp, ghost + (right * r), frame.Width, frame.Height) is { } edge)
            {
                shapes.Add(new AidShape(g, g, Vector2.Distance(g, edge), GhostColour));
            }
            var centre = (sim.Balls[sim.IndexOf(ball)].Position with { Z = 0 }).ToVector3() + lift;
            var from = sim.Balls[sim.IndexOf(ball)].Position;
            double run = Math.Min(ObjectLineLength, AimPreview.ToCushion(from, preview.ObjectDirection, physics.Table, physics.BallRadius));
            var end = centre + (preview.ObjectDirection.ToVector3() * (float)run);
            if (Segment(vp, frame, centre, end, ObjectColour) is { } objectLine)
            {
                shapes.Add(objectLine);
            }
        }
        return shapes;
    }

    private static readonly Vector4 CallColour = new(0.3f, 0.9f, 1f, 0.9f);

    /// <summary>
    /// The call marked on the table for <paramref name="frame"/>'s camera (pixels): a ring round
    /// the called ball and one round the called pocket's mouth; none when the shot is not called,
    /// the balls roll, or there is no call. Shown whether or not the aim line is.
    /// </summary>
    public IReadOnlyList<AidShape> CallShapes(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        // A call marks its ball and pocket; a snooker nomination (a colour, a free ball) its ball.
        var call = _match switch
        {
            { NeedsCall: true, Call.CurrentCall: { } c } => c,
            { NeedsNomination: true, Call.CurrentNomination: { } n } => n,
            _ => null,
        };
        if (call is null || _cue is not { IsVisible: true } || _physics is not { } physics)
        {
            return [];
        }
        var sim = physics.Simulation;
        var vp = RenderMath.ViewProjection(frame);
        var right = Vector3.Normalize(Vector3.Cross(frame.Target - frame.Eye, Vector3.UnitZ));
        var shapes = new List<AidShape>(2);
        void Ring(Vector3 centre, float radius)
        {
            if (RenderMath.ToPixel(vp, centre, frame.Width, frame.Height) is { } c && RenderMath.ToPixel(vp, centre + (right * radius), frame.Width, frame.Height) is { } edge)
            {
                shapes.Add(new AidShape(c, c, MathF.Max(4, Vector2.Distance(c, edge)), CallColour));
            }
        }
        float r = (float)physics.BallRadius;
        if (sim.IndexOf(call.Ball) is >= 0 and var i && !sim.Balls[i].IsPocketed)
        {
            Ring((sim.Balls[i].Position with { Z = 0 }).ToVector3() + new Vector3(0, 0, r), 1.35f * r);
        }
        foreach (var pocket in _pockets)
        {
            if (pocket.Pocket == call.Pocket.Index)
            {
                Ring((pocket.Centre with { Z = 0 }).ToVector3(), (float)pocket.Radius + r);
            }
        }
        return shapes;
    }

    private static AidShape? Segment(Matrix4x4 vp, RenderFrame frame, Vector3 a, Vector3 b, Vector4 colour) =>
        RenderMath.ToPixel(vp, a, frame.Width, frame.Height) is { } pa && RenderMath.ToPixel(vp, b, frame.Width, frame.Height) is { } pb
            ? new AidShape(pa, pb, 0, colour)
            : null;
}
