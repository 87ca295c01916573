using System.Numerics;
using Billiards.Core.Balls;
using Billiards.Core.Table;

namespace Billiards.App.Rendering;

/// <summary>
/// Everything the renderer draws in one frame, as plain data: the game builds it from Core's
/// state (interpolated between physics steps), the renderer only reads it. World units are
/// Core's: metres, z up, origin at the centre of the bed.
/// </summary>
public sealed class RenderFrame
{
    /// <summary>Framebuffer size in pixels.</summary>
    public int Width { get; set; } = 1280;

    /// <summary>Framebuffer size in pixels.</summary>
    public int Height { get; set; } = 720;

    /// <summary>The share of the height at the top the camera leaves to the HUD's scoreboard (<see cref="RenderMath.HudInset"/>); 0 frames the whole window (offscreen scene renders).</summary>
    public float TopInset { get; set; }

    /// <summary>The table to draw.</summary>
    public required TableSpec Table { get; set; }

    /// <summary>The set the balls belong to: how each of them looks.</summary>
    public Core.Balls.BallSet BallSet { get; set; } = Core.Balls.BallSet.Pool;

    /// <summary>Camera position (m).</summary>
    public Vector3 Eye { get; set; } = new(-2.2f, 0, 1.2f);

    /// <summary>Point the camera looks at (m).</summary>
    public Vector3 Target { get; set; } = Vector3.Zero;

    /// <summary>Vertical field of view (deg).</summary>
    public float FovYDegrees { get; set; } = 45;

    /// <summary>Ball radius (m); the scene's model decides it (standard 28.575 mm, thesis 28.6 mm).</summary>
    public float BallRadius { get; set; } = 0.028575f;

    /// <summary>The balls; pocketed balls that have dropped out of sight have Visible = false.</summary>
    public List<BallVisual> Balls { get; } = [];

    /// <summary>The cue; hidden while balls roll.</summary>
    public CueVisual Cue { get; set; }

    /// <summary>HUD and help overlay; null draws none (e.g. for `render`).</summary>
    public HudInfo? Hud { get; set; }

    /// <summary>Draw the collision geometry and its normals (debug toggle).</summary>
    public bool ShowCollisionGeometry { get; set; }

    /// <summary>Debug collision triangles (corners and unit normal, m) to draw when <see cref="ShowCollisionGeometry"/> is on.</summary>
    public IReadOnlyList<DebugTriangle> CollisionTriangles { get; set; } = [];
}

/// <summary>One ball as drawn.</summary>
/// <param name="Id">Which ball (its texture).</param>
/// <param name="Position">Centre (m).</param>
/// <param name="Orientation">Orientation quaternion.</param>
/// <param name="Visible">False once it has dropped out of sight.</param>
public readonly record struct BallVisual(BallId Id, Vector3 Position, Quaternion Orientation, bool Visible = true);

/// <summary>The cue as drawn (seed 4.5.3): it points at the cue ball along the aim, tilted by the elevation.</summary>
/// <param name="Visible">False while balls roll.</param>
/// <param name="BallCentre">Centre of the cue ball (m).</param>
/// <param name="AimDirection">Unit direction of the stroke in the bed plane.</param>
/// <param name="ElevationDegrees">Cue elevation above the bed (deg).</param>
/// <param name="PullBack">Distance of the tip from the ball's surface (m), the seed's offset d.</param>
/// <param name="TipOffset">Tip offset on the ball [side, height] as fractions of R.</param>
public readonly record struct CueVisual(bool Visible, Vector3 BallCentre, Vector3 AimDirection, float ElevationDegrees, float PullBack, Vector2 TipOffset);

/// <summary>What the HUD shows.</summary>
/// <param name="Lines">Text lines (mode, last shot's speed, elevation, frame rate...).</param>
/// <param name="SpinPoint">Tip offset on the cue-ball diagram [side, height] as fractions of R.</param>
/// <param name="ShowHelp">Whether the help overlay is open.</param>
/// <param name="HelpLines">Lines of the help overlay: every key.</param>
/// <param name="Power">The power meter while stroking (and briefly after), or null.</param>
/// <param name="Aids">Aim aids drawn under the HUD's panel (the aim line and its ghost ball), or null.</param>
/// <param name="Icons">Ball icons drawn after text lines (the balls each player still needs), or null.</param>
/// <param name="Buttons">Clickable buttons (menus, the incoming player's options), or null.</param>
/// <param name="Title">A title over the buttons (a menu's question), or null.</param>
public sealed record HudInfo(IReadOnlyList<string> Lines, Vector2 SpinPoint, bool ShowHelp, IReadOnlyList<string> HelpLines, PowerMeter? Power = null, IReadOnlyList<AidShape>? Aids = null,
    IReadOnlyList<HudIcon>? Icons = null, IReadOnlyList<HudButton>? Buttons = null, string? Title = null)
{
    /// <summary>The match's scoreboard along the top edge, or null outside a match (then the lines are the HUD).</summary>
    public Hud.Scoreboard? Board { get; init; }

    /// <summary>True when the developer lines (<see cref="Lines"/>: mode, raw numbers, frame rate) are shown beside the scoreboard (F2).</summary>
    public bool Developer { get; init; }

    /// <summary>The cue's settings as small diagrams (spin point, elevation, power), or null while balls roll.</summary>
    public Hud.CueGauges? Gauges { get; init; }

    /// <summary>The result panel at the end of a game, or null.</summary>
    public Hud.ResultPanel? Result { get; init; }

    /// <summary>Text a menu screen places itself (its title, headings, notes), or null.</summary>
    public IReadOnlyList<HudLabel>? Labels { get; init; }

    /// <summary>True when a menu screen covers the view with its dark backdrop (the start menu's screens).</summary>
    public bool Backdrop { get; init; }
}

/// <summary>Text a menu places in pixels (x right, y down): its top left corner, or its top centre when <paramref name="Centred"/>.</summary>
/// <param name="X">Left, or centre (pixels).</param>
/// <param name="Y">Top (pixels).</param>
/// <param name="Text">The text.</param>
/// <param name="Size">Its size as a multiple of the HUD's text (a title 3, a heading 1).</param>
/// <param name="Gold">Drawn in the HUD's gold (titles, headings) rather than its text colour.</param>
/// <param name="Centred">Centred on <paramref name="X"/>.</param>
public readonly record struct HudLabel(float X, float Y, string Text, int Size = 1, bool Gold = false, bool Centred = false);

/// <summary>A small top view of a position: the bed's half sizes and the balls on it (a drill's picture in the menu).</summary>
/// <param name="HalfLength">Half the playing length (m).</param>
/// <param name="HalfWidth">Half the playing width (m).</param>
/// <param name="Balls">The balls: position on the bed (m, from its centre) and the ball's number (0 for the cue ball).</param>
/// <param name="Pockets">The pockets' mouths (m), the first <paramref name="Targets"/> of them the ones to play.</param>
/// <param name="Targets">How many of <paramref name="Pockets"/>, from the start, are the drill's pockets.</param>
public sealed record HudPicture(float HalfLength, float HalfWidth, IReadOnlyList<(Vector2 At, int Number)> Balls, IReadOnlyList<Vector2> Pockets, int Targets);

/// <summary>A ball icon after a HUD line: a small disc in the ball's colour with its number.</summary>
/// <param name="Line">Index of the line it follows.</param>
/// <param name="Number">The ball's number (1-15).</param>
public readonly record struct HudIcon(int Line, int Number);

/// <summary>A button in pixels (x right, y down from the top left); the game hit-tests the same rectangle.</summary>
/// <param name="X">Left (pixels).</param>
/// <param name="Y">Top (pixels).</param>
/// <param name="Width">Width (pixels).</param>
/// <param name="Height">Height (pixels).</param>
/// <param name="Label">Its text.</param>
public readonly record struct HudButton(float X, float Y, float Width, float Height, string Label)
{
    /// <summary>The option chosen (drawn filled in gold): the menu marks a choice by colour, so that no label changes its width.</summary>
    public bool Chosen { get; init; }

    /// <summary>The keyboard's focus (drawn with a bright frame): Enter presses it.</summary>
    public bool Focused { get; init; }

    /// <summary>Smaller text under the label (a drill's goal), wrapped to the button, or null.</summary>
    public string? Note { get; init; }

    /// <summary>A picture above the label (a drill's position), or null.</summary>
    public HudPicture? Picture { get; init; }

    /// <summary>A card's text scale (its title, its margins and picture; see <see cref="CardLayout"/>), or null for the HUD's.</summary>
    public int? TextScale { get; init; }

    /// <summary>A card's goal's text scale, or null for one smaller than <see cref="TextScale"/> (at least 1).</summary>
    public int? NoteScale { get; init; }

    /// <summary>True when the pixel lies on the button.</summary>
    public bool Contains(Vector2 p) => p.X >= X && p.X < X + Width && p.Y >= Y && p.Y < Y + Height;
}

/// <summary>An aim aid in pixels (x right, y down): a line from <paramref name="A"/> to <paramref name="B"/>, or with a radius a ring around <paramref name="A"/>.</summary>
/// <param name="A">Start of the line, or the ring's centre (pixels).</param>
/// <param name="B">End of the line (pixels; ignored for a ring).</param>
/// <param name="Radius">The ring's radius (pixels), 0 for a line.</param>
/// <param name="Color">Colour and opacity (sRGB, alpha).</param>
public readonly record struct AidShape(Vector2 A, Vector2 B, float Radius, Vector4 Color);

/// <summary>The power meter under the table view.</summary>
/// <param name="Fraction">How full the bar is, 0..1 (of the strongest stroke, or of the longest backswing).</param>
/// <param name="Label">Its text, e.g. "Power 3.20 m/s".</param>
/// <param name="Pushing">True for the push's speed (or the shot played), false for the backswing.</param>
public sealed record PowerMeter(float Fraction, string Label, bool Pushing);

/// <summary>A collision triangle for the debug view (m).</summary>
public readonly record struct DebugTriangle(Vector3 A, Vector3 B, Vector3 C, Vector3 Normal);
