using System.Globalization;
using System.Numerics;
using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.App.Rendering;
using Billiards.Core.Ai;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Rules;
using Billiards.Core.Table;

namespace Billiards.App.Game;

/// <summary>
/// The diamond aid of three-cushion (<see cref="ToggleKey"/>, on the carom table only): for the aim,
/// speed and spin the player has set, the cue ball's path to its third cushion as our physics plays
/// the stroke (<see cref="DiamondAid"/>), drawn on the cloth; each cushion contact is ringed and
/// labelled with its count and its corner-5 diamond number, and the cue ball with the line's origin
/// number D and first-rail number F, beside the formula's third rail T = D - F. The path is
/// simulated again only when the stroke or the balls change.
/// </summary>
public sealed class DiamondAidNode : Node
{
    /// <summary>The key that shows or hides the aid.</summary>
    public const Key ToggleKey = Key.F4;

    private static readonly Vector4 PathColour = new(1f, 0.85f, 0.2f, 0.9f);
    private static readonly Vector4 ContactColour = new(1f, 0.85f, 0.2f, 1f);

    // Just above the cloth, as the tracking lines.
    private const float ClothLift = 0.002f;

    private PhysicsNode? _physics;
    private CueNode? _cue;
    private MatchNode? _match;
    private PracticeNode? _practice;
    private (ShotSpec Shot, Vec3 Sum)? _traced;

    /// <summary>True while the aid is shown.</summary>
    public bool Visible { get; private set; }

    /// <summary>The path for the stroke set now, or null when the aid is off or cannot be drawn.</summary>
    public DiamondPath? Path { get; private set; }

    /// <summary>The stroke <see cref="Path"/> was simulated for, or null.</summary>
    public ShotSpec? Shot => Path is null ? null : _traced?.Shot;

    /// <summary>True on a table the aid reads: a pocketless table (the carom table) and its diamonds, whatever game is played on it.</summary>
    public bool Available => _physics is { Table.HasPockets: false };

    /// <inheritdoc />
    protected override void Ready()
    {
        _physics = GetInTree<PhysicsNode>();
        _cue = FindInTree<CueNode>();
        _match = FindInTree<MatchNode>();
        _practice = FindInTree<PracticeNode>();
    }

    /// <inheritdoc />
    protected override bool Input(InputEvent e)
    {
        if (e is KeyInput { Pressed: true, Key: ToggleKey } && Available)
        {
            Visible = !Visible;
            return true;
        }
        return false;
    }

    /// <inheritdoc />
    protected override void Process(double dt)
    {
        if (!Visible || _cue is not { IsVisible: true } cue || _physics is not { IsRolling: false, HasCueBall: true } physics
            || _match is { Session.IsComputerActing: true } or { Session.IsOver: true })
        {
            Path = null;
            _traced = null;
            return;
        }
        double power = _match?.Power ?? _practice?.Power ?? MatchNode.DefaultPower;
        var shot = cue.MakeShot(power);
        var sim = physics.Simulation;
        var sum = Vec3.Zero;
        foreach (var b in sim.Balls)
        {
            sum += b.Position;
        }
        if (Path is not null && _traced is { } t && t.Shot == shot && t.Sum == sum)
        {
            return;
        }
        _traced = (shot, sum);
        Path = DiamondAid.Trace(sim.TableModel, TablePosition.Of(sim, physics.CueBall), shot);
    }

    /// <summary>The path and its contact rings for <paramref name="frame"/>'s camera (pixels); none when the aid is off.</summary>
    public IReadOnlyList<AidShape> Shapes(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        if (Path is not { } path || _physics is null)
        {
            return [];
        }
        var vp = RenderMath.ViewProjection(frame);
        var shapes = new List<AidShape>(path.Path.Count + 3);
        Vector2? last = null;
        foreach (var p in path.Path)
        {
            var next = Pixel(vp, frame, p);
            if (last is { } a && next is { } b && a != b)
            {
                shapes.Add(new AidShape(a, b, 0, PathColour));
            }
            last = next;
        }
        var right = Vector3.Normalize(Vector3.Cross(frame.Target - frame.Eye, Vector3.UnitZ));
        float r = (float)(0.5 * _physics.BallRadius);
        foreach (var c in path.Contacts)
        {
            if (Pixel(vp, frame, c.Centre) is { } at && RenderMath.ToPixel(vp, Cloth(c.Centre) + (right * r), frame.Width, frame.Height) is { } edge)
            {
                shapes.Add(new AidShape(at, at, MathF.Max(4, Vector2.Distance(at, edge)), ContactColour));
            }
        }
        return shapes;
    }

    /// <summary>
    /// The labels for <paramref name="frame"/>'s camera (pixels): "1: 2.9" beside each contact (its
    /// count and diamond number), and by the cue ball "D 5.0  F 2.0: T = 3.0" (the formula's third
    /// rail) when the line starts where the corner-5 system numbers it.
    /// </summary>
    public IReadOnlyList<HudLabel> Labels(RenderFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        if (Path is not { } path)
        {
            return [];
        }
        var c = CultureInfo.InvariantCulture;
        var vp = RenderMath.ViewProjection(frame);
        var labels = new List<HudLabel>(path.Contacts.Count + 1);
        foreach (var k in path.Contacts)
        {
            if (Pixel(vp, frame, k.Centre) is { } at)
            {
                labels.Add(new HudLabel(at.X + 8, at.Y - 22, ContactLabel(k), Gold: true));
            }
        }
        if (path.FormulaThirdRail is { } t && Pixel(vp, frame, path.Path[0]) is { } cueAt)
        {
            labels.Add(new HudLabel(cueAt.X + 12, cueAt.Y + 8, string.Create(c, $"D {path.Origin:0.0}  F {path.FirstRail:0.0}: T = D - F = {t:0.0}")));
        }
        return labels;
    }

    /// <summary>A contact's label: its count and its diamond number to a tenth, e.g. "3: 2.9".</summary>
    public static string ContactLabel(CushionContact contact) => string.Create(CultureInfo.InvariantCulture, $"{contact.Count}: {contact.Diamond:0.0}");

    private static Vector3 Cloth(Vec3 p) => new((float)p.X, (float)p.Y, ClothLift);

    private static Vector2? Pixel(Matrix4x4 vp, RenderFrame frame, Vec3 p) => RenderMath.ToPixel(vp, Cloth(p), frame.Width, frame.Height);
}
