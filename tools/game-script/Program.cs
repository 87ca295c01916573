using System.Globalization;
using System.Numerics;
using System.Text;
using Billiards.App.Game;
using Billiards.App.Platform;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

// Makes a whole scripted 8-ball game between two people (assets/scripts/eight-ball-game.json):
// shot by shot it tries key sequences (B to pick the ball, X to aim at its ghost ball, W/Q for the
// power, Space; a mouse drag in move mode with ball in hand) by playing the whole script so far
// through the game itself, and keeps the best by the referee's ruling: a win, then a scratch once
// (after the third shot), then a pot, then a legal miss. Deterministic: same code, same script.
// With --snooker it makes a whole snooker frame between two people (assets/scripts/snooker-frame.json):
// the break-off from the D, pots of reds and of nominated colours while they are found (B to pick
// the ball, which also nominates it, X, the power, Space), else the best legal shot found, and,
// after four pots or sixteen turns, the player at the table misses on purpose and the other has the balls replaced
// (key 3) until the third foul and a miss with a full view of the ball on ends the frame.
// Usage: dotnet run --project tools/game-script -c Release -- [--snooker] OUT.json | [--snooker] --check SCRIPT.json
internal static class Program
{
    private const double Speed = 16;
    private static Scene s_scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "eight-ball.json"));
    private static GameRules s_rules = GameRules.EightBall;

    private static int Main(string[] args)
    {
        if (args.Length > 0 && args[0] == "--snooker")
        {
            s_scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "snooker.json"));
            s_rules = GameRules.Snooker;
            args = args[1..];
        }
        if (args.Length == 2 && args[0] == "--check")
        {
            var script = InputScript.Load(args[1]);
            foreach (double frame in new[] { 1.0 / 60, 0.05, 0.3 })
            {
                var (match, _) = Run([.. script.Events], frame);
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"frames of {frame:0.000} s: {match.Rulings.Count} rulings, winner {match.Winner}"));
                foreach (var r in match.Rulings)
                {
                    Console.WriteLine("  " + r.Message);
                }
            }
            return 0;
        }
        if (args.Length != 1)
        {
            Console.Error.WriteLine("usage: game-script OUT.json | --check SCRIPT.json");
            return 2;
        }
        var events = s_rules == GameRules.Snooker ? SnookerSearch() : Search();
        File.WriteAllText(args[0], ToJson(events));
        return 0;
    }

    private static List<ScriptEvent> Search()
    {
        var events = new List<ScriptEvent>();
        bool scratched = false;
        for (int turn = 0; turn < 60; turn++)
        {
            var (match, host) = Run(events, 0.05);
            if (match.IsOver)
            {
                Console.WriteLine($"game over: {match.State.Players[match.Winner ?? 0]} wins");
                break;
            }
            var sim = host.World.Physics.Simulation;
            int onTable = 0;
            for (int i = 0; i < sim.Ids.Count; i++)
            {
                if (sim.Ids[i].Value != 0 && !sim.Balls[i].IsPocketed)
                {
                    onTable++;
                }
            }
            double start = Math.Round((events.Count > 0 ? events[^1].Time : 0) + 0.3, 2);
            var candidates = new List<List<ScriptEvent>>();
            if (match.State.Shot == 0)
            {
                for (int tweak = -6; tweak <= 6; tweak += 2)
                {
                    candidates.Add(Shot(events, start, 8, 0, tweak, null, aimAtGhost: false, match.Power));
                }
            }
            else
            {
                (int, int)?[] drags = match.State.BallInHand != BallInHand.None ? [(0, -40), (40, -20), (-40, -20), (0, 40), (60, 0)] : [null];
                foreach (var drag in drags)
                {
                    for (int b = 0; b < onTable; b++)
                    {
                        foreach (double power in new[] { 2.0, 3.5 })
                        {
                            candidates.Add(Shot(events, start, power, b, 0, drag, aimAtGhost: true, match.Power));
                        }
                    }
                }
            }
            double best = double.NegativeInfinity;
            List<ScriptEvent>? bestEvents = null;
            Ruling? bestRuling = null;
            foreach (var candidate in candidates)
            {
                var (m, _) = Run(candidate, 0.05);
                if (m.Rulings.Count != match.Rulings.Count + 1)
                {
                    continue;
                }
                var r = m.LastRuling!;
                bool scratch = r.Fouls.Contains(Foul.CueBallPocketed);
                double score = r.GameOver ? (r.Winner == match.State.Shooter ? 100 : -100)
                    : scratch ? (!scratched && turn >= 3 ? 50 : -1)
                    : r.Options.Count > 0 ? -50
                    : r.Legal && r.Continue ? 10 + r.Pocketed.Count
                    : r.Legal ? 1 : 0;
                if (score > best)
                {
                    (best, bestEvents, bestRuling) = (score, candidate, r);
                }
                if (score >= 50)
                {
                    break;
                }
            }
            scratched |= bestRuling!.Fouls.Contains(Foul.CueBallPocketed);
            events = bestEvents!;
            Console.WriteLine($"shot {turn}: {bestRuling.Message}");
        }
        return events;
    }

    // The snooker frame (see the file's head): the break-off, then each turn the best of the key
    // sequences tried (a pot that keeps the player at the table, the most points first; else a
    // legal shot), and from the fourth pot or the sixteenth turn on, the misses.
    private static List<ScriptEvent> SnookerSearch()
    {
        var events = new List<ScriptEvent>();
        int pots = 0;
        int? misser = null;
        for (int turn = 0; turn < 80; turn++)
        {
            var (match, host) = Run(events, 0.05);
            if (match.IsOver)
            {
                Console.WriteLine($"frame over: {match.LastRuling!.Message}");
                break;
            }
            double start = Math.Round((events.Count > 0 ? events[^1].Time : 0) + 0.3, 2);
            if (match.PendingOptions.Count > 0)
            {
                // After the misses the other player has the balls replaced; after any other foul plays on.
                var option = match.PendingOptions.Contains(RefereeOption.Replace) && misser is not null ? RefereeOption.Replace : RefereeOption.Play;
                events = Choose(events, start, match.PendingOptions.ToList().IndexOf(option));
                Console.WriteLine($"turn {turn}: {match.State.ShooterName} chooses {option.ToName()}");
                continue;
            }
            if (misser is not null)
            {
                events = Shot(events, start, 0.5, 0, 0, null, aimAtGhost: true, match.Power, turnDegrees: 180);
                Console.WriteLine($"turn {turn}: {match.State.ShooterName} misses");
                continue;
            }
            var sim = host.World.Physics.Simulation;
            int onTable = 0;
            for (int i = 0; i < sim.Ids.Count; i++)
            {
                onTable += sim.Ids[i].Value != 0 && !sim.Balls[i].IsPocketed ? 1 : 0;
            }
            var candidates = new List<List<ScriptEvent>>();
            // Each ball in turn (B), aimed at its ghost ball (X), at two powers: the break-off
            // is played so too, firmly, into a red of the pack.
            double[] powers = match.State.Shot == 0 ? [3.0, 4.5] : [1.5, 2.5];
            for (int b = 0; b < onTable; b++)
            {
                foreach (double power in powers)
                {
                    candidates.Add(Shot(events, start, power, b, 0, null, aimAtGhost: true, match.Power));
                }
            }
            double best = double.NegativeInfinity;
            List<ScriptEvent>? bestEvents = null;
            Ruling? bestRuling = null;
            foreach (var candidate in candidates)
            {
                var (m, _) = Run(candidate, 0.05);
                if (m.Rulings.Count != match.Rulings.Count + 1)
                {
                    continue;
                }
                var r = m.LastRuling!;
                double score = r.GameOver ? -100 : r.Legal && r.Continue ? 10 + r.Points : r.Legal ? 1 : -10;
                if (score > best)
                {
                    (best, bestEvents, bestRuling) = (score, candidate, r);
                }
            }
            bool potted = bestRuling is { Legal: true, Continue: true };
            if (turn > 0 && (pots >= 4 || turn >= 16))
            {
                // Nothing to pot, or enough pots: from here the player at the table misses.
                misser = match.State.Shooter;
                turn--;
                continue;
            }
            pots += potted ? 1 : 0;
            events = bestEvents!;
            Console.WriteLine($"turn {turn}: {bestRuling!.Message}");
        }
        return events;
    }

    // The incoming player presses the option's key (1 for the first).
    private static List<ScriptEvent> Choose(List<ScriptEvent> prefix, double start, int index)
    {
        var events = new List<ScriptEvent>(prefix);
        var key = Key.D1 + index;
        events.Add(new ScriptEvent(start, ScriptAction.KeyDown, Key: key));
        events.Add(new ScriptEvent(Math.Round(start + 0.02, 2), ScriptAction.KeyUp, Key: key));
        return events;
    }

    private static (MatchNode Match, GameHost Host) Run(List<ScriptEvent> events, double frameSeconds)
    {
        var clock = new ManualClock();
        var scriptClock = new ScriptClock(clock);
        var script = new InputScript(events, (events.Count > 0 ? events[^1].Time : 0) + 0.1, Speed);
        var scripted = new ScriptedInput(new NoWindow(), script, scriptClock);
        var match = new MatchSetup(s_rules, [new MatchPlayer("Anna"), new MatchPlayer("Ben")]);
        var host = new GameHost(s_scene, SimulationFactory.Create, scripted, scriptClock, match) { TimeScale = Speed };
        scripted.IsAtRest = () => host.IsSettled;
        bool warm = false;
        host.FrameStarting += now =>
        {
            // As play does: the first frame loads the table, the script starts with the second.
            if (warm)
            {
                scripted.Pump(now);
            }
            warm = true;
        };
        for (int i = 0; i < 1_000_000 && !scripted.Finished; i++)
        {
            clock.Advance(frameSeconds);
            host.RunFrame();
        }
        return (host.Tree.Root.GetInTree<MatchNode>(), host);
    }

    private static List<ScriptEvent> Shot(List<ScriptEvent> prefix, double start, double power, int ballPresses, int aimTweak, (int X, int Y)? drag, bool aimAtGhost, double powerNow, int turnDegrees = 0)
    {
        var events = new List<ScriptEvent>(prefix);
        double t = start;
        void Add(ScriptEvent e)
        {
            events.Add(e with { Time = t });
            t = Math.Round(t + 0.02, 2);
        }
        void Press(Key key, int times = 1)
        {
            for (int i = 0; i < times; i++)
            {
                events.Add(new ScriptEvent(t, ScriptAction.KeyDown, Key: key));
                Add(new ScriptEvent(t, ScriptAction.KeyUp, Key: key));
            }
        }
        if (drag is { } d)
        {
            Press(Key.M);
            Add(new ScriptEvent(0, ScriptAction.MouseMove, Vector: new Vector2(640, 360)));
            Add(new ScriptEvent(0, ScriptAction.MouseDown, Button: MouseButton.Left));
            for (int s = 0; s < 4; s++)
            {
                Add(new ScriptEvent(0, ScriptAction.MouseMoveBy, Vector: new Vector2(d.X / 4f, d.Y / 4f)));
            }
            Add(new ScriptEvent(0, ScriptAction.MouseUp, Button: MouseButton.Left));
            Press(Key.V);
        }
        Press(Key.B, ballPresses);
        if (aimAtGhost)
        {
            Press(Key.X);
        }
        Press(aimTweak > 0 ? Key.A : Key.D, Math.Abs(aimTweak));
        Press(Key.Left, turnDegrees);
        int steps = (int)Math.Round((power - powerNow) / MatchNode.PowerStep);
        Press(steps > 0 ? Key.W : Key.Q, Math.Abs(steps));
        Press(Key.Space);
        Add(new ScriptEvent(0, ScriptAction.WaitRest));
        return events;
    }

    private static string ToJson(List<ScriptEvent> events)
    {
        var c = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.Append("{\n  \"format\": \"billiards-input-script/1\",\n  \"speed\": 16,\n");
        sb.Append(c, $"  \"duration\": {events[^1].Time + 2:0.00},\n  \"events\": [\n");
        for (int i = 0; i < events.Count; i++)
        {
            var e = events[i];
            string action = e.Action switch
            {
                ScriptAction.KeyDown => $"\"key_down\": \"{e.Key}\"",
                ScriptAction.KeyUp => $"\"key_up\": \"{e.Key}\"",
                ScriptAction.MouseMove => string.Create(c, $"\"mouse_move\": [{e.Vector.X}, {e.Vector.Y}]"),
                ScriptAction.MouseMoveBy => string.Create(c, $"\"mouse_move_by\": [{e.Vector.X}, {e.Vector.Y}]"),
                ScriptAction.MouseDown => "\"mouse_down\": \"left\"",
                ScriptAction.MouseUp => "\"mouse_up\": \"left\"",
                ScriptAction.WaitRest => "\"wait\": \"rest\"",
                _ => throw new InvalidOperationException($"no JSON for {e.Action}"),
            };
            sb.Append(c, $"    {{ \"t\": {e.Time:0.00}, {action} }}{(i + 1 < events.Count ? "," : "")}\n");
        }
        sb.Append("  ]\n}\n");
        return sb.ToString();
    }

    private sealed class NoWindow : IGameWindow
    {
        public event Action<Key>? KeyDown { add { } remove { } }

        public event Action<Key>? KeyUp { add { } remove { } }

        public event Action<Vector2>? MouseMove { add { } remove { } }

        public event Action<MouseButton>? MouseDown { add { } remove { } }

        public event Action<MouseButton>? MouseUp { add { } remove { } }

        public event Action<float>? Scroll { add { } remove { } }

        public event Action<int, int>? Resize { add { } remove { } }

        public (int Width, int Height) FramebufferSize => (1280, 720);

        public void SetMouseCaptured(bool captured)
        {
        }

        public void ToggleFullscreen()
        {
        }

        public void Close()
        {
        }
    }
}
