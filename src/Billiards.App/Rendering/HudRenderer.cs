using System.Numerics;
using Billiards.App.Native;

namespace Billiards.App.Rendering;

/// <summary>
/// Draws <see cref="HudInfo"/> over the scene in pixel coordinates: the text lines on a dark
/// panel (top left), the cue-ball diagram with the spin point (bottom right) and the help
/// overlay (centred). Text uses <see cref="HudFont"/>'s antialiased atlas.
/// </summary>
internal sealed class HudRenderer : IDisposable
{
    private const int Floats = 9; // position 2, uv 2, colour 4, kind 1

    private readonly Gl _gl;
    private readonly uint _program, _vao, _vbo;
    private uint _font;
    private int _fontScale;
    private readonly int _screen, _fontSampler;
    private readonly List<float> _vertices = [];
    private readonly HudLayer _layer;
    private readonly Action<bool> _submit;

    // The help overlay has a layer of its own: it is the same whenever it opens, so opening and
    // closing it put back a stored texture instead of redrawing thousands of glyphs, and the HUD's
    // own layer stays stored meanwhile.
    private readonly List<float> _help = [];
    private readonly HudLayer _helpLayer;
    private readonly Action<bool> _submitHelp;

    // The aim line and the ghost ball follow the camera: drawn straight onto the frame under the
    // HUD, not into its stored layer, which a moving camera would otherwise redraw every frame.
    private readonly List<float> _aids = [];

    // The list the quad helpers append to: the HUD's, the aids' or the help overlay's.
    private List<float> _out;
    private int _width, _height;

    public HudRenderer(Gl gl)
    {
        _gl = gl;
        _layer = new HudLayer(gl);
        _helpLayer = new HudLayer(gl);
        _submit = premultiplied => Submit(_vertices, premultiplied);
        _submitHelp = premultiplied => Submit(_help, premultiplied);
        _out = _vertices;
        _program = gl.LinkProgram(gl.CompileShader(Gl.VertexShader, Shaders.HudVertex),
            gl.CompileShader(Gl.FragmentShader, Shaders.HudFragment), ["aPosition", "aUv", "aColor", "aKind"]);
        _screen = gl.GetUniformLocation(_program, "uScreen");
        _fontSampler = gl.GetUniformLocation(_program, "uFont");
        _vao = gl.GenVertexArray();
        _vbo = gl.GenBuffer();
        gl.BindVertexArray(_vao);
        gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        const int Bytes = Floats * sizeof(float);
        gl.VertexAttribPointer(0, 2, Gl.Float, false, Bytes, 0);
        gl.VertexAttribPointer(1, 2, Gl.Float, false, Bytes, 2 * sizeof(float));
        gl.VertexAttribPointer(2, 4, Gl.Float, false, Bytes, 4 * sizeof(float));
        gl.VertexAttribPointer(3, 1, Gl.Float, false, Bytes, 8 * sizeof(float));
        for (uint i = 0; i < 4; i++)
        {
            gl.EnableVertexAttribArray(i);
        }
        gl.BindVertexArray(0);

    }

    /// <summary>Makes the font atlas for <paramref name="scale"/> pixels a HUD unit, unless it is already made.</summary>
    private void EnsureFont(int scale)
    {
        if (scale == _fontScale)
        {
            return;
        }
        if (_font != 0)
        {
            _gl.DeleteTexture(_font);
        }
        _fontScale = scale;
        _font = _gl.GenTexture();
        _gl.BindTexture(Gl.Texture2D, _font);
        _gl.PixelStore(Gl.UnpackAlignment, 1);
        _gl.TexImage2D(Gl.Texture2D, 0, Gl.R8, HudFont.Columns * HudFont.CellWidth * scale, HudFont.Rows * HudFont.LineHeight * scale, Gl.Red, Gl.UnsignedByte, HudFont.Atlas(scale));
        // Mipmaps for text drawn smaller than the atlas (a help overlay fitted to a narrow window).
        _gl.GenerateMipmap(Gl.Texture2D);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMinFilter, Gl.LinearMipmapLinear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureMagFilter, Gl.Linear);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapS, Gl.ClampToEdge);
        _gl.TexParameter(Gl.Texture2D, Gl.TextureWrapT, Gl.ClampToEdge);
    }

    /// <summary>Text scale (pixels per font pixel) for a framebuffer height.</summary>
    public static int Scale(int height) => Math.Max(1, height / 360);

    public void Draw(HudInfo hud, int width, int height, Billiards.Core.Balls.BallSet balls)
    {
        ArgumentNullException.ThrowIfNull(balls);
        _balls = balls;
        _width = width;
        _height = height;
        _vertices.Clear();
        _out = _vertices;
        int scale = Scale(height);
        EnsureFont(scale);
        int lineHeight = HudFont.LineHeight * scale;
        int margin = 8 * scale;
        var textColor = new Vector4(0.95f, 0.95f, 0.9f, 1);
        var panel = new Vector4(0, 0, 0, 0.45f);

        _aids.Clear();
        if (hud.Aids is { } aids)
        {
            // Under the panel: the aim line's segments as thin quads, the ghost ball as a ring.
            _out = _aids;
            foreach (var aid in aids)
            {
                if (aid.Radius > 0)
                {
                    Disc(aid.A, aid.Radius, aid.Color, 3);
                }
                else
                {
                    Line(aid.A, aid.B, 1.5f * scale, aid.Color);
                }
            }
            _out = _vertices;
            if (_aids.Count > 0)
            {
                Submit(_aids, premultiplied: false);
            }
        }

        float top = 0;
        if (hud.Board is { } board)
        {
            top = Board(board, width, scale, textColor);
        }
        if (hud.Result is { } result)
        {
            Result(result, width, height, scale, textColor);
        }
        // The developer lines: the whole HUD outside a match, behind F2 beside the scoreboard.
        if (hud.Lines.Count > 0 && (hud.Board is null || hud.Developer))
        {
            float icon = lineHeight;
            float widest = 0;
            for (int i = 0; i < hud.Lines.Count; i++)
            {
                int icons = hud.Board is null ? hud.Icons?.Count(c => c.Line == i) ?? 0 : 0;
                widest = MathF.Max(widest, (HudFont.Width(hud.Lines[i]) * scale) + (icons > 0 ? (icons + 0.5f) * icon : 0));
            }
            Rect(margin, top + margin, widest + (2 * margin), (hud.Lines.Count * lineHeight) + (2 * margin) - (2 * scale), panel);
            for (int i = 0; i < hud.Lines.Count; i++)
            {
                Text(hud.Lines[i], 2 * margin, top + (2 * margin) + (i * lineHeight), scale, textColor);
            }
            if (hud.Icons is { } iconList && hud.Board is null)
            {
                var next = new Dictionary<int, int>();
                foreach (var ic in iconList)
                {
                    if (ic.Line < 0 || ic.Line >= hud.Lines.Count)
                    {
                        continue;
                    }
                    int k = next.GetValueOrDefault(ic.Line);
                    next[ic.Line] = k + 1;
                    float x = (2 * margin) + (HudFont.Width(hud.Lines[ic.Line]) * scale) + ((k + 1) * icon);
                    BallIcon(new Vector2(x, top + (2 * margin) + (ic.Line * lineHeight) + (lineHeight / 2f) - scale), icon * 0.47f, ic.Number, scale);
                }
            }
        }

        if (hud.Backdrop)
        {
            // The start menu's screens: a dark room over the table, opaque so the layer copies it.
            Rect(0, 0, width, height, new Vector4(0.02f, 0.05f, 0.03f, 1));
            Rect(0, 0, width, 3 * scale, Gold);
        }
        foreach (var label in hud.Labels ?? [])
        {
            int size = scale * Math.Max(1, label.Size);
            float lx = label.Centred ? label.X - (HudFont.Width(label.Text) * size / 2) : label.X;
            Text(label.Text, lx, label.Y, size, label.Gold ? Gold : textColor);
        }
        if (hud.Buttons is { Count: > 0 } menuButtons && hud.Backdrop)
        {
            foreach (var b in menuButtons)
            {
                MenuButton(b, scale, textColor);
            }
        }
        else if (hud.Buttons is { Count: > 0 } buttons)
        {
            if (hud.Title is { } title)
            {
                float tw = HudFont.Width(title) * scale;
                float ty = buttons.Min(b => b.Y) - (2 * lineHeight);
                Rect(((width - tw) / 2) - margin, ty - margin, tw + (2 * margin), lineHeight + (2 * margin) - (2 * scale), new Vector4(0.02f, 0.03f, 0.02f, 1));
                Text(title, (width - tw) / 2, ty, scale, textColor);
            }
            foreach (var b in buttons)
            {
                // Opaque, so that the stored layer copies them instead of blending.
                Rect(b.X, b.Y, b.Width, b.Height, new Vector4(0.8f, 0.7f, 0.3f, 1));
                Rect(b.X + scale, b.Y + scale, b.Width - (2 * scale), b.Height - (2 * scale), new Vector4(0.05f, 0.12f, 0.07f, 1));
                float lw = HudFont.Width(b.Label) * scale;
                Text(b.Label, b.X + ((b.Width - lw) / 2), b.Y + ((b.Height - lineHeight) / 2) + scale, scale, textColor);
            }
        }

        if (hud.Gauges is { } gauges)
        {
            Gauges(gauges, width, height, scale);
        }

        if (hud.Power is { } power)
        {
            // Under the view, centred: a bar with its label above it.
            float barW = 160 * scale, barH = 7 * scale;
            float bx = (width - barW) / 2, by = height - margin - barH;
            Rect(bx - scale, by - scale, barW + (2 * scale), barH + (2 * scale), new Vector4(0, 0, 0, 0.6f));
            var fill = power.Pushing ? new Vector4(0.95f, 0.55f + (0.4f * (1 - power.Fraction)), 0.1f, 0.95f) : new Vector4(0.6f, 0.6f, 0.6f, 0.9f);
            Rect(bx, by, barW * Math.Clamp(power.Fraction, 0, 1), barH, fill);
            float labelW = HudFont.Width(power.Label) * scale;
            Text(power.Label, (width - labelW) / 2, by - lineHeight - scale, scale, textColor);
        }

        _layer.Draw(_vertices, Floats, width, height, _submit);

        if (hud.ShowHelp && hud.HelpLines.Count > 0)
        {
            _help.Clear();
            _out = _help;
            // The overlay fits the window: a smaller text scale first, then texts wrapped.
            int helpScale = scale;
            var lines = hud.HelpLines;
            var natural = HelpLayout.Layout(lines, float.MaxValue, HudFont.Width);
            while (helpScale > 1 && (natural.Width * helpScale) + (4 * margin) > width)
            {
                helpScale--;
            }
            float fit = MathF.Max(60, (width - (4 * margin)) / helpScale);
            // Laid out again only when the texts must wrap.
            var (runs, across, rows) = natural.Width <= fit ? natural : HelpLayout.Layout(lines, fit, HudFont.Width);
            int helpLine = HudFont.LineHeight * helpScale;
            float w = (across * helpScale) + (4 * margin);
            float h = (rows * helpLine) + (4 * margin);
            float x = MathF.Max(0, (width - w) / 2), y = MathF.Max(0, (height - h) / 2);
            // Opaque: the layer copies it back instead of blending the largest panel (HudLayer).
            Rect(x, y, w, h, new Vector4(0.02f, 0.03f, 0.02f, 1));
            Rect(x, y, w, scale, new Vector4(0.8f, 0.7f, 0.3f, 1));
            foreach (var run in runs)
            {
                Text(run.Text, x + (2 * margin) + (run.X * helpScale), y + (2 * margin) + (run.Row * helpLine), helpScale, run.Title ? Gold : textColor);
            }
            _out = _vertices;
            _helpLayer.Draw(_help, Floats, width, height, _submitHelp);
        }
    }

    private static readonly Vector4 Gold = new(0.95f, 0.78f, 0.3f, 1);
    private static readonly Vector4 Dim = new(0.75f, 0.78f, 0.72f, 1);

    /// <summary>Player cards' width in HUD units (pixels at scale 1).</summary>
    public const int CardUnits = 150;

    /// <summary>Rows of the scoreboard's centre the band is always tall enough for (the camera frames the table below them).</summary>
    public const int BoardRows = 5;

    /// <summary>The scoreboard band's height in HUD units: <see cref="BoardRows"/> lines and the padding, the cards' height being less.</summary>
    public const int BoardUnits = (2 * 4) + (BoardRows * HudFont.LineHeight);

    /// <summary>The width (HUD units) of the scoreboard's centre column in a window <paramref name="width"/> pixels wide at <paramref name="scale"/>.</summary>
    public static float BoardCentreUnits(int width, int scale)
    {
        float u = scale, pad = 4 * u;
        float card = MathF.Min(CardUnits * u, width * 0.28f);
        float centreW = width - (2 * (card + (2 * pad)));
        return MathF.Max(60, (centreW - (2 * pad)) / scale);
    }

    /// <summary>
    /// The scoreboard's centre rows, each with its colour (0 text, 1 gold, 2 dim): the game's line,
    /// who acts (wrapped), the whole message (wrapped, never cut: it is what the player reads), then
    /// as many of the earlier rulings as fit in <see cref="BoardRows"/>, each whole.
    /// </summary>
    public static List<(string Text, int Colour)> CentreRows(Hud.Scoreboard board, float width, Func<string, float> measure)
    {
        ArgumentNullException.ThrowIfNull(board);
        ArgumentNullException.ThrowIfNull(measure);
        var rows = new List<(string Text, int Colour)> { (board.Title, 0) };
        var status = WrapStatus(board.Status, width, measure);
        rows.Add((status[0], 1));
        foreach (string l in status.Skip(1))
        {
            rows.Add(("  " + l.TrimStart(), 1));
        }
        if (board.Message is { } message)
        {
            rows.AddRange(Wrap([message], width, measure).Select(l => (l, 0)));
        }
        foreach (string l in board.Log)
        {
            var wrapped = Wrap([l], width, measure);
            if (rows.Count + wrapped.Count > BoardRows)
            {
                break;
            }
            rows.AddRange(wrapped.Select(w => (w, 2)));
        }
        return rows;
    }

    /// <summary>
    /// The scoreboard along the top edge: a card for each player at the sides (name, the balls still
    /// needed as big icons, target and fouls or score), and between them the game's line, who acts
    /// and how, the message wrapped to fit, and the earlier rulings. Returns the band's height (px).
    /// </summary>
    private float Board(Hud.Scoreboard board, int width, int scale, Vector4 text)
    {
        float u = scale, pad = 4 * u, line = HudFont.LineHeight * scale;
        float card = MathF.Min(CardUnits * u, width * 0.28f);
        float centreX = card + (2 * pad), centreW = width - (2 * centreX);
        var rows = CentreRows(board, BoardCentreUnits(width, scale), HudFont.Width);
        string title = board.Title;
        bool cornerBeside = (HudFont.Width(title) + HudFont.Width(board.Corner) + 12) * scale <= centreW - (2 * pad);
        float icon = 16 * u;
        float cardH = pad + line + (2 * u) + icon + (2 * u) + line + pad;
        float bandH = MathF.Max(BoardUnits * u, (2 * pad) + (rows.Count * line));
        Rect(0, 0, width, bandH, new Vector4(0, 0, 0, 0.55f));
        for (int i = 0; i < rows.Count; i++)
        {
            Text(rows[i].Text, centreX + pad, pad + (i * line), scale, rows[i].Colour switch { 1 => Gold, 2 => Dim, _ => text });
        }
        if (cornerBeside)
        {
            Text(board.Corner, centreX + centreW - pad - (HudFont.Width(board.Corner) * scale), pad, scale, Dim);
        }
        float cardWidth = MathF.Max(36, (card - (3 * pad)) / scale);
        for (int p = 0; p < board.Players.Count && p < 2; p++)
        {
            var player = board.Players[p];
            float x = p == 0 ? pad : width - pad - card;
            if (player.AtTable)
            {
                Rect(x, pad, 2 * u, cardH - (2 * pad), Gold);
            }
            float tx = x + pad;
            var (nameRow, besideName, ballRow, infoRow) = CardRows(player, cardWidth, HudFont.Width);
            Text(nameRow, tx, pad, scale, player.AtTable ? Gold : text);
            if (besideName is not null)
            {
                Text(besideName, x + card - pad - (HudFont.Width(besideName) * scale), pad, scale, Dim);
            }
            int fit = Math.Max(1, (int)((card - (2 * pad)) / icon));
            int shown = player.Balls.Count > fit ? fit - 1 : player.Balls.Count;
            float iy = pad + line + (2 * u) + (icon / 2);
            for (int k = 0; k < shown; k++)
            {
                BallIcon(new Vector2(tx + (icon / 2) + (k * icon), iy), icon * 0.45f, player.Balls[k], scale);
            }
            if (shown < player.Balls.Count)
            {
                Text($"+{player.Balls.Count - shown}", tx + (shown * icon), iy - (line / 2), scale, text);
            }
            if (ballRow is not null)
            {
                Text(ballRow, tx, iy - (line / 2), scale, text);
            }
            Text(infoRow, tx, pad + line + (4 * u) + icon, scale, Dim);
        }
        return bandH;
    }

    /// <summary>As <see cref="CardRows(Hud.PlayerCard, float, Func{string, float})"/> with one column a character.</summary>
    public static (string Name, string? BesideName, string? BallRow, string Info) CardRows(Hud.PlayerCard player, int columns) => CardRows(player, columns, s => s.Length);

    /// <summary>
    /// A player card's text in <paramref name="width"/> (as <paramref name="measure"/> measures): the name row, what stands right-aligned
    /// beside the name (or null), the text in the balls' row of a card without balls (or null),
    /// and the row under the balls. The target and the detail share the lower row where they fit;
    /// where they do not ("71, free ball: black" and "break 12"), the detail moves up beside the
    /// name, or, where the name leaves no room and the card draws no balls (14.1's "3 balls on the
    /// table" and "score 99 of 100  run 4"), the target takes the balls' row, rather than be cut off.
    /// </summary>
    public static (string Name, string? BesideName, string? BallRow, string Info) CardRows(Hud.PlayerCard player, float width, Func<string, float> measure)
    {
        ArgumentNullException.ThrowIfNull(player);
        ArgumentNullException.ThrowIfNull(measure);
        string name = Cut(player.Name, width, measure);
        string joined = player.Detail.Length > 0 ? $"{player.Target}  {player.Detail}" : player.Target;
        if (measure(joined) <= width || player.Detail.Length == 0)
        {
            return (name, null, null, Cut(joined, width, measure));
        }
        if (measure($"{player.Name}  {player.Detail}") <= width)
        {
            return (name, player.Detail, null, Cut(player.Target, width, measure));
        }
        return player.Balls.Count == 0
            ? (name, null, Cut(player.Target, width, measure), Cut(player.Detail, width, measure))
            : (name, null, null, Cut(joined, width, measure));
    }

    // The status line's parts are joined by ";  ": a long one breaks between parts where it can
    // ("FREE BALL: nominate pink (B, click a ball);" / "Space shoots, G hint"), else at a space.
    private static List<string> WrapStatus(string status, float width, Func<string, float> measure)
    {
        if (measure(status) > width)
        {
            for (int cut = status.LastIndexOf(";  ", StringComparison.Ordinal); cut > 0; cut = status.LastIndexOf(";  ", cut - 1, StringComparison.Ordinal))
            {
                if (measure(status[..(cut + 1)]) <= width)
                {
                    return [status[..(cut + 1)], .. Wrap([status[(cut + 3)..]], width, measure)];
                }
            }
        }
        return Wrap([status], width, measure);
    }

    // A name too long for its card: cut with an ellipsis (names only; messages are wrapped).
    private static string Cut(string text, float width, Func<string, float> measure)
    {
        if (measure(text) <= width)
        {
            return text;
        }
        int n = text.Length;
        while (n > 0 && measure(string.Concat(text.AsSpan(0, n), "...")) > width)
        {
            n--;
        }
        return string.Concat(text.AsSpan(0, n), "...");
    }

    /// <summary>
    /// The cue's settings in the bottom right corner as diagrams: the power as a bar, the
    /// elevation as the cue's angle over a quarter circle, the tip's point on the cue ball.
    /// </summary>
    private void Gauges(Hud.CueGauges gauges, int width, int height, int scale)
    {
        float u = scale, pad = 4 * u;
        float r = 22 * u, column = (2 * r) + (6 * u);
        float x0 = width - pad - column, cx = x0 + (column / 2);
        float fan = 2 * r;
        float power = gauges.Power is null ? 0 : 9 * u;
        float h = (2 * r) + (6 * u) + fan + (4 * u) + power + (2 * u);
        float y0 = height - pad - h;
        Rect(x0, y0, column, h, new Vector4(0, 0, 0, 0.45f));
        float y = y0 + (3 * u);
        if (gauges.Power is float share)
        {
            float barW = column - (8 * u);
            Rect(x0 + (4 * u), y, barW, 5 * u, new Vector4(0.25f, 0.25f, 0.25f, 0.9f));
            Rect(x0 + (4 * u), y, barW * Math.Clamp(share, 0, 1), 5 * u, new Vector4(0.95f, 0.55f + (0.4f * (1 - share)), 0.1f, 0.95f));
            y += power;
        }
        // Elevation: a quarter circle from level to upright, the cue drawn at its angle.
        var pivot = new Vector2(x0 + (5 * u), y + fan);
        float arm = fan - (2 * u);
        Line(pivot, pivot + new Vector2(arm, 0), u, Dim);
        for (int k = 0; k < 9; k++)
        {
            float a0 = k * MathF.PI / 18, a1 = (k + 1) * MathF.PI / 18;
            Line(pivot + (arm * new Vector2(MathF.Cos(a0), -MathF.Sin(a0))), pivot + (arm * new Vector2(MathF.Cos(a1), -MathF.Sin(a1))), u, new Vector4(0.6f, 0.6f, 0.6f, 0.8f));
        }
        float e = Math.Clamp(gauges.ElevationDegrees, 0, 90) * MathF.PI / 180;
        Line(pivot, pivot + (arm * new Vector2(MathF.Cos(e), -MathF.Sin(e))), 3 * u, Gold);
        Disc(pivot, 3 * u, new Vector4(0.93f, 0.93f, 0.88f, 1), 2);
        // The angle in degrees in the corner the quarter circle leaves free: a jump shot's 55 is
        // told apart from 50 at a glance, which the cue's line alone does not do.
        string degrees = Math.Round(Math.Clamp(gauges.ElevationDegrees, 0, 90)).ToString("0", System.Globalization.CultureInfo.InvariantCulture);
        float ring = 1.5f * u, textW = HudFont.Width(degrees) * scale;
        float tx = x0 + column - (3 * u) - (2 * ring) - u - textW;
        Text(degrees, tx, pivot.Y - arm, scale, Gold);
        Disc(new Vector2(tx + textW + u + ring, pivot.Y - arm + (2 * u)), ring, Gold, 3);
        y += fan + (4 * u);
        // The cue ball with the tip's contact point.
        var centre = new Vector2(cx, y + r);
        Disc(centre, r, new Vector4(0.93f, 0.93f, 0.88f, 1), 2);
        Rect(centre.X - r, centre.Y - (0.5f * u), 2 * r, u, new Vector4(0.6f, 0.6f, 0.6f, 0.8f));
        Rect(centre.X - (0.5f * u), centre.Y - r, u, 2 * r, new Vector4(0.6f, 0.6f, 0.6f, 0.8f));
        // The miscue limit (the tip in the cue's frame, scene-format.md): past this ring the tip slides off.
        float limit = (float)Core.Physics.PhysicsParams.Pool.MiscueLimit * r;
        for (int k = 0; k < 36; k++)
        {
            float a0 = k * MathF.PI / 18, a1 = (k + 1) * MathF.PI / 18;
            Line(centre + (limit * new Vector2(MathF.Cos(a0), MathF.Sin(a0))), centre + (limit * new Vector2(MathF.Cos(a1), MathF.Sin(a1))), u, new Vector4(0.75f, 0.35f, 0.3f, 0.8f));
        }
        var spin = new Vector2(Math.Clamp(gauges.Spin.X, -1, 1), Math.Clamp(gauges.Spin.Y, -1, 1));
        var point = centre + new Vector2(spin.X * r, -spin.Y * r);
        Disc(point, 4 * u, new Vector4(0.85f, 0.1f, 0.1f, 1), 2);
        Disc(point, 5 * u, new Vector4(0.2f, 0, 0, 1), 3);
    }

    /// <summary>
    /// The result panel: who won, then each player's shots, pots, fouls, best run and games won in
    /// two columns; opaque, above the Rematch and Menu buttons (laid out at 0.66 of the height).
    /// </summary>
    private void Result(Hud.ResultPanel result, int width, int height, int scale, Vector4 text)
    {
        float u = scale, pad = 8 * u, line = HudFont.LineHeight * scale * 1.25f;
        var rows = result.Rows;
        float w = MathF.Min(width - (8 * u), MathF.Max(280 * u, (HudFont.Width(result.Title) * scale) + (2 * pad)));
        float h = (2 * pad) + ((rows.Count + 2.5f) * line);
        float x = (width - w) / 2, y = MathF.Max(0, (height * 0.64f) - h);
        Rect(x, y, w, h, new Vector4(0.02f, 0.05f, 0.03f, 1));
        Rect(x, y, w, 2 * u, Gold);
        float tw = HudFont.Width(result.Title) * scale;
        Text(result.Title, x + ((w - tw) / 2), y + pad, scale, Gold);
        float c1 = x + (w * 0.56f), c2 = x + (w * 0.82f);
        float ry = y + pad + (1.5f * line);
        float nameWidth = MathF.Max(24, w * 0.25f / scale);
        void Centred(string s, float cx, float yy, Vector4 colour) => Text(s, cx - (HudFont.Width(s) * scale / 2), yy, scale, colour);
        Centred(Cut(result.Names.First, nameWidth, HudFont.Width), c1, ry, text);
        Centred(Cut(result.Names.Second, nameWidth, HudFont.Width), c2, ry, text);
        for (int i = 0; i < rows.Count; i++)
        {
            float yy = ry + ((i + 1) * line);
            Text(rows[i].Label, x + pad, yy, scale, Dim);
            Centred(rows[i].First, c1, yy, text);
            Centred(rows[i].Second, c2, yy, text);
        }
    }

    // A start-menu button: a frame (bright when focused), filled gold when it is the choice made; a
    // drill's card has its picture above the label and its goal wrapped under it.
    private void MenuButton(HudButton b, int scale, Vector4 text)
    {
        float u = scale, line = HudFont.LineHeight * scale;
        var frame = b.Focused ? new Vector4(1f, 0.95f, 0.7f, 1) : new Vector4(0.55f, 0.48f, 0.22f, 1);
        float edge = b.Focused ? 2 * u : u;
        Rect(b.X, b.Y, b.Width, b.Height, frame);
        var fill = b.Chosen ? new Vector4(0.78f, 0.62f, 0.2f, 1) : b.Focused ? new Vector4(0.1f, 0.22f, 0.13f, 1) : new Vector4(0.05f, 0.12f, 0.07f, 1);
        Rect(b.X + edge, b.Y + edge, b.Width - (2 * edge), b.Height - (2 * edge), fill);
        var ink = b.Chosen ? new Vector4(0.05f, 0.05f, 0.03f, 1) : text;
        if (b.Picture is null)
        {
            float lw = HudFont.Width(b.Label) * scale;
            Text(b.Label, b.X + ((b.Width - lw) / 2), b.Y + ((b.Height - line) / 2) + u, scale, ink, shadow: !b.Chosen);
            return;
        }
        // A card: drawn at its own text scale, as the menu measured it (CardLayout).
        int cardScale = b.TextScale ?? scale;
        float pad = CardLayout.Pad(cardScale);
        float pw = b.Width - (2 * pad), ph = CardLayout.PictureHeight(b.Width, cardScale);
        Picture(b.Picture, b.X + pad, b.Y + pad, pw, ph, cardScale);
        float ty = b.Y + pad + ph + (2 * cardScale);
        var lines = CardLayout.Text(b.Label, b.Note, b.Width, cardScale, b.NoteScale ?? Math.Max(1, cardScale - 1));
        foreach (string t in lines.Title)
        {
            Text(t, b.X + pad, ty, lines.TitleScale, Gold);
            ty += HudFont.LineHeight * lines.TitleScale;
        }
        foreach (string l in lines.Note)
        {
            Text(l, b.X + pad, ty, lines.NoteScale, text, shadow: false);
            ty += HudFont.LineHeight * lines.NoteScale;
        }
    }

    // A position from above in the rectangle: the cloth, the pockets (the ones to play ringed in
    // gold) and the balls in their colours.
    private void Picture(HudPicture p, float x, float y, float w, float h, int scale)
    {
        float s = MathF.Min(w / (2 * p.HalfLength * 1.08f), h / (2 * p.HalfWidth * 1.16f));
        var centre = new Vector2(x + (w / 2), y + (h / 2));
        Vector2 At(Vector2 m) => centre + new Vector2(m.X * s, -m.Y * s);
        float rail = 0.06f * s;
        Rect(centre.X - (p.HalfLength * s) - rail, centre.Y - (p.HalfWidth * s) - rail, (2 * p.HalfLength * s) + (2 * rail), (2 * p.HalfWidth * s) + (2 * rail), new Vector4(0.35f, 0.18f, 0.08f, 1));
        Rect(centre.X - (p.HalfLength * s), centre.Y - (p.HalfWidth * s), 2 * p.HalfLength * s, 2 * p.HalfWidth * s, new Vector4(0.1f, 0.45f, 0.2f, 1));
        float pocket = MathF.Max(2 * scale, 0.055f * s);
        for (int i = 0; i < p.Pockets.Count; i++)
        {
            if (i < p.Targets)
            {
                Disc(At(p.Pockets[i]), pocket * 1.6f, Gold, 2);
            }
            Disc(At(p.Pockets[i]), pocket, new Vector4(0.02f, 0.02f, 0.02f, 1), 2);
        }
        float r = MathF.Max(1.5f * scale, 0.0286f * s * 1.3f);
        foreach (var (at, number) in p.Balls)
        {
            if (number == 0)
            {
                Disc(At(at), r, new Vector4(0.97f, 0.96f, 0.92f, 1), 2);
            }
            else
            {
                var colour = _balls.Contains(new Billiards.Core.Balls.BallId(number)) ? new Vector4(BallTextures.BaseColor(_balls, new Billiards.Core.Balls.BallId(number)), 1) : new Vector4(0.8f, 0.1f, 0.1f, 1);
                Disc(At(at), r, colour, 2);
            }
        }
    }

    /// <summary>Frames whose HUD was put back from the stored layer.</summary>
    public long Reused => _layer.Reused;

    /// <summary>Frames whose help overlay was put back from its stored layer.</summary>
    public long HelpReused => _helpLayer.Reused;

    private void Submit(List<float> vertices, bool premultiplied)
    {
        _gl.Disable(Gl.DepthTest);
        _gl.Enable(Gl.Blend);
        if (premultiplied)
        {
            _gl.BlendFuncSeparate(Gl.SrcAlpha, Gl.OneMinusSrcAlpha, Gl.One, Gl.OneMinusSrcAlpha);
        }
        else
        {
            _gl.BlendFunc(Gl.SrcAlpha, Gl.OneMinusSrcAlpha);
        }
        _gl.UseProgram(_program);
        _gl.Uniform2(_screen, _width, _height);
        _gl.Uniform1(_fontSampler, 0);
        _gl.ActiveTexture(Gl.Texture0);
        _gl.BindTexture(Gl.Texture2D, _font);
        _gl.BindVertexArray(_vao);
        _gl.BindBuffer(Gl.ArrayBuffer, _vbo);
        var data = System.Runtime.InteropServices.CollectionsMarshal.AsSpan(vertices);
        _gl.BufferData<float>(Gl.ArrayBuffer, data, Gl.DynamicDraw);
        _gl.DrawArrays(Gl.Triangles, 0, vertices.Count / Floats);
        _gl.Disable(Gl.Blend);
        _gl.Enable(Gl.DepthTest);
    }

    /// <summary>Wraps lines longer than <paramref name="columns"/> characters at spaces, continuing with the line's indentation plus two.</summary>
    public static List<string> Wrap(IReadOnlyList<string> lines, int columns) => Wrap(lines, columns, s => s.Length);

    /// <summary>
    /// Wraps lines wider than <paramref name="width"/> (as <paramref name="measure"/> measures) at
    /// spaces, continuing with the line's indentation plus two; a word wider than the line breaks
    /// between characters. No text is dropped.
    /// </summary>
    public static List<string> Wrap(IReadOnlyList<string> lines, float width, Func<string, float> measure)
    {
        ArgumentNullException.ThrowIfNull(lines);
        ArgumentNullException.ThrowIfNull(measure);
        var result = new List<string>();
        foreach (string line in lines)
        {
            string rest = line;
            int lead = line.Length - line.TrimStart().Length;
            string indent = new(' ', lead + 2);
            if (measure(indent) > width / 2)
            {
                indent = "";
            }
            while (measure(rest) > width)
            {
                int start = rest.Length - rest.TrimStart().Length, cut = -1;
                for (int i = rest.IndexOf(' ', start); i > 0; i = rest.IndexOf(' ', i + 1))
                {
                    if (measure(rest[..i]) > width)
                    {
                        break;
                    }
                    cut = i;
                }
                if (cut <= start)
                {
                    cut = start + 1;
                    while (cut < rest.Length && measure(rest[..(cut + 1)]) <= width)
                    {
                        cut++;
                    }
                }
                result.Add(rest[..cut].TrimEnd());
                rest = indent + rest[cut..].TrimStart();
            }
            result.Add(rest);
        }
        return result;
    }

    private void Vertex(float x, float y, float u, float v, Vector4 c, float kind)
    {
        _out.Add(x); _out.Add(y); _out.Add(u); _out.Add(v);
        _out.Add(c.X); _out.Add(c.Y); _out.Add(c.Z); _out.Add(c.W);
        _out.Add(kind);
    }

    private void Quad(float x, float y, float w, float h, float u0, float v0, float u1, float v1, Vector4 c, float kind)
    {
        Vertex(x, y, u0, v0, c, kind);
        Vertex(x + w, y, u1, v0, c, kind);
        Vertex(x + w, y + h, u1, v1, c, kind);
        Vertex(x, y, u0, v0, c, kind);
        Vertex(x + w, y + h, u1, v1, c, kind);
        Vertex(x, y + h, u0, v1, c, kind);
    }

    private void Line(Vector2 a, Vector2 b, float width, Vector4 c)
    {
        var d = b - a;
        float length = d.Length();
        if (length < 0.5f)
        {
            return;
        }
        var n = new Vector2(-d.Y, d.X) * (0.5f * width / length);
        Vertex(a.X + n.X, a.Y + n.Y, 0, 0, c, 0);
        Vertex(b.X + n.X, b.Y + n.Y, 0, 0, c, 0);
        Vertex(b.X - n.X, b.Y - n.Y, 0, 0, c, 0);
        Vertex(a.X + n.X, a.Y + n.Y, 0, 0, c, 0);
        Vertex(b.X - n.X, b.Y - n.Y, 0, 0, c, 0);
        Vertex(a.X - n.X, a.Y - n.Y, 0, 0, c, 0);
    }

    // The set whose looks the icons are drawn with (the frame's).
    private Billiards.Core.Balls.BallSet _balls = Billiards.Core.Balls.BallSet.Pool;

    // A ball of the set seen from above, as its look says: its colour (a white disc with a
    // coloured band for a stripe) and, for a numbered ball, a white spot with its name in ink.
    private void BallIcon(Vector2 centre, float radius, int number, int scale)
    {
        var id = new Billiards.Core.Balls.BallId(number);
        if (!_balls.Contains(id))
        {
            return;
        }
        var kind = _balls.Kind(id);
        var colour = BallTextures.BaseColor(_balls, id);
        var c = new Vector4(colour, 1);
        if (kind.Look.Striped)
        {
            Disc(centre, radius, new Vector4(0.97f, 0.96f, 0.92f, 1), 2);
            Quad(centre.X - radius, centre.Y - (radius * 0.55f), 2 * radius, radius * 1.1f, 0, 0, 0, 0, c, 0);
        }
        else
        {
            Disc(centre, radius, c, 2);
        }
        if (!kind.Look.Numbered)
        {
            return;
        }
        Disc(centre, radius * 0.6f, new Vector4(0.97f, 0.96f, 0.92f, 1), 2);
        int small = Math.Max(1, scale - 1);
        string text = kind.Name;
        float tw = HudFont.Width(text) * small;
        Text(text, centre.X - (tw / 2), centre.Y - (HudFont.LineHeight * small / 2f), small, new Vector4(0.05f, 0.05f, 0.05f, 1), shadow: false);
    }

    private void Rect(float x, float y, float w, float h, Vector4 c) => Quad(x, y, w, h, 0, 0, 0, 0, c, 0);

    private void Disc(Vector2 centre, float radius, Vector4 c, int kind) =>
        Quad(centre.X - radius, centre.Y - radius, 2 * radius, 2 * radius, -1, -1, 1, 1, c, kind);

    private void Text(string text, float x, float y, int scale, Vector4 color, bool shadow = true)
    {
        float atlasW = HudFont.Columns * HudFont.CellWidth, atlasH = HudFont.Rows * HudFont.LineHeight;
        float cellW = HudFont.CellWidth * scale, cellH = HudFont.LineHeight * scale, origin = HudFont.Origin * scale;
        foreach (char ch in text)
        {
            int c = ch is >= ' ' and <= '~' ? ch : '?';
            if (c != ' ')
            {
                int cell = c - 32;
                float u0 = cell % HudFont.Columns * HudFont.CellWidth / atlasW, v0 = cell / HudFont.Columns * HudFont.LineHeight / atlasH;
                float u1 = u0 + (HudFont.CellWidth / atlasW), v1 = v0 + (HudFont.LineHeight / atlasH);
                // On whole pixels, one atlas texel on one pixel: a glyph placed between pixels would
                // filter in its neighbour's ink (an underscore's over an 'o' in the row below it).
                float gx = MathF.Round(x - origin), gy = MathF.Round(y);
                // A one-pixel drop shadow keeps text readable on the bright cloth.
                if (shadow)
                {
                    Quad(gx + scale, gy + scale, cellW, cellH, u0, v0, u1, v1, new Vector4(0, 0, 0, 0.8f), 1);
                }
                Quad(gx, gy, cellW, cellH, u0, v0, u1, v1, color, 1);
            }
            x += HudFont.AdvanceOf((char)c) * scale;
        }
    }

    public void Dispose()
    {
        _gl.DeleteBuffer(_vbo);
        _gl.DeleteVertexArray(_vao);
        _gl.DeleteTexture(_font);
        _gl.DeleteProgram(_program);
        _layer.Dispose();
        _helpLayer.Dispose();
    }
}
