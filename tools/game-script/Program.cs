using System.Globalization;
using System.Numerics;
using System.Text;
using Billiards.App.Camera;
using Billiards.App.Game;
using Billiards.App.Input.Modes;
using Billiards.App.Rendering;
using Billiards.Core.Ai;
using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.App.Platform;
using Billiards.Core.Rules;
using Billiards.Core.Scenes;

// Makes a whole scripted 8-ball game between two people (assets/scripts/eight-ball-game.json):
// shot by shot it tries key sequences (B to pick the ball, X to aim at its ghost ball, W/Q for the
// power, Space; a mouse drag in move mode with ball in hand) by playing the whole script so far
// through the game itself, and keeps the best by the referee's ruling: a win, then a scratch once
// (after the third shot), then a pot, then a legal miss. Deterministic: same code, same script.
// With --snooker it makes a whole snooker frame between two people (assets/scripts/snooker-frame.json)
// in one pass through one game that plays the script as it grows: each turn the computer player's
// planner (level 4, centre ball only) picks the shot from the table as it stands, for a person to
// play it through the real input: ball in hand dragged in move mode (M, V), the colour nominated
// by a click on it from the view above the table (T) or by B, X to aim at its ghost ball, whole
// degrees on Left/Right and the rest by a drag of the view, W/Q for the power, Space; after a
// foul the option the planner would choose is clicked on its button. --seed picks the planner's
// seeds (the frame shipped is seed 4: it ends on the black potted, with an in-off along the way).
// With --three-cushion it makes a whole three-cushion game against the computer (level 4), a race to
// 3 on assets/scenes/three-cushion-race.json (assets/scripts/three-cushion-game.json): on each of
// Anna's turns a hint (G), waited for, then Space.
// Usage: dotnet run --project tools/game-script -c Release -- [--snooker] [--seed N] OUT.json | [--snooker] --check SCRIPT.json
// or --three-cushion OUT.json
internal static class Program
{
    private const double Speed = 16;

    // The snooker frame plays at the script's top speed, its keys a hundredth of a second apart: a
    // long frame in a short time.
    private const double SnookerSpeed = 64, EventGap = 0.01;

    // The three-cushion game's computer (--three-cushion): Anna plays its hints against it.
    private const int CaromComputerLevel = 4;
    private static Scene s_scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "eight-ball.json"));
    private static GameRules s_rules = GameRules.EightBall;
    private static Seat[] s_seats = [new Seat("Anna"), new Seat("Ben")];

    private static int Main(string[] args)
    {
        if (args.Length > 0 && args[0] == "--snooker")
        {
            s_scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "snooker.json"));
            s_rules = GameRules.Snooker;
            args = args[1..];
        }
        if (args.Length > 0 && args[0] == "--three-cushion")
        {
            s_scene = SceneLoader.Load(Path.Combine(AssetFolder.Assets, "scenes", "three-cushion-race.json"));
            s_rules = "three-cushion";
            s_seats = [new Seat("Anna"), Seat.Parse($"computer:{CaromComputerLevel}", 1)!];
            args = args[1..];
            if (args.Length == 1)
            {
                File.WriteAllText(args[0], ToJson(CaromGame(200), SnookerSpeed, 4));
                return 0;
            }
        }
        ulong seed = 4;
        if (args.Length > 2 && args[0] == "--seed" && ulong.TryParse(args[1], out ulong chosen))
        {
            seed = chosen;
            args = args[2..];
        }
        if (args.Length == 2 && args[0] == "--check")
        {
            var script = InputScript.Load(args[1]);
            foreach (double frame in new[] { 1.0 / 60, 0.05, 0.3 })
            {
                var (match, _) = Run([.. script.Events], frame, script.Speed);
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"frames of {frame:0.000} s: {match.Session.Rulings.Count} rulings, winner {match.Session.Winner}"));
                foreach (var r in match.Session.Rulings)
                {
                    Console.WriteLine("  " + r.Message);
                }
            }
            return 0;
        }
        if (args.Length == 4 && args[0] == "--split")
        {
            return Split(args[1], args[2], args[3]);
        }
        if (args.Length != 1)
        {
            Console.Error.WriteLine("usage: game-script OUT.json | --check SCRIPT.json | --split SCRIPT.json HOST.json JOIN.json");
            return 2;
        }
        var events = s_rules == GameRules.Snooker ? SnookerFrame(4, seed, 400) : Search();
        File.WriteAllText(args[0], ToJson(events, s_rules == GameRules.Snooker ? SnookerSpeed : Speed, s_rules == GameRules.Snooker ? 4 : 2));
        return 0;
    }

    // A game of two people at one table split into the two scripts of a networked game: each
    // shot's events (up to its wait for rest) go to the script of the seat that played it, after a
    // wait for rest (over the network a wait also lasts through the other player's turn), with W/Q
    // presses first where the one keyboard power of the table differed from this side's own.
    private static int Split(string scriptPath, string hostPath, string joinPath)
    {
        var script = InputScript.Load(scriptPath);
        var (match, _) = Run([.. script.Events], 0.05, script.Speed);
        var shots = match.Session.Shots;
        var segments = new List<List<ScriptEvent>> { new() };
        foreach (var e in script.Events)
        {
            segments[^1].Add(e);
            if (e.Action == ScriptAction.WaitRest)
            {
                segments.Add([]);
            }
        }
        segments.RemoveAll(g => g.Count == 0);
        if (segments.Count != shots.Count || match.Session.PendingOptions.Count > 0 || match.Session.Rulings.Any(r => r.Options.Count > 0))
        {
            Console.Error.WriteLine($"game-script: {scriptPath}: {segments.Count} shots of events for {shots.Count} shots played, or an option chosen: cannot split it");
            return 2;
        }
        double table = MatchNode.DefaultPower;
        double[] own = [MatchNode.DefaultPower, MatchNode.DefaultPower];
        var sides = new List<ScriptEvent>[] { [], [] };
        static double Step(double power, Key key) => key switch
        {
            Key.W => Math.Min(MatchNode.MaxPower, power + MatchNode.PowerStep),
            Key.Q => Math.Max(MatchNode.MinPower, power - MatchNode.PowerStep),
            _ => power,
        };
        for (int k = 0; k < shots.Count; k++)
        {
            var before = shots[k].Before;
            int seat = before.Shooter;
            var side = sides[seat];
            var first = segments[k][0];
            side.Add(new ScriptEvent(first.Time, ScriptAction.WaitRest));
            int steps = (int)Math.Round((table - own[seat]) / MatchNode.PowerStep);
            for (int i = 0; i < Math.Abs(steps); i++)
            {
                var key = steps > 0 ? Key.W : Key.Q;
                side.Add(new ScriptEvent(first.Time, ScriptAction.KeyDown, Key: key));
                side.Add(new ScriptEvent(first.Time, ScriptAction.KeyUp, Key: key));
                own[seat] = Step(own[seat], key);
            }
            foreach (var e in segments[k])
            {
                side.Add(e);
                if (e.Action == ScriptAction.KeyDown)
                {
                    table = Step(table, e.Key);
                    own[seat] = Step(own[seat], e.Key);
                }
            }
            if (before.Shot == 0 && match.Ruleset.PowerBreak)
            {
                // The break's power is the break's alone, on either side's keyboard.
                table = Math.Min(table, MatchNode.DefaultPower);
                own[seat] = Math.Min(own[seat], MatchNode.DefaultPower);
            }
        }
        // Each side waits for the end of the game before its script ends.
        double end = script.Events[^1].Time;
        foreach (var side in sides)
        {
            side.Add(new ScriptEvent(end, ScriptAction.WaitRest));
        }
        File.WriteAllText(hostPath, ToJson(sides[0], script.Speed, 2));
        File.WriteAllText(joinPath, ToJson(sides[1], script.Speed, 2));
        Console.WriteLine($"{shots.Count} shots: {sides[0].Count(e => e.Action == ScriptAction.KeyDown && e.Key == Key.Space)} by {match.State.Players[0]} (host), {sides[1].Count(e => e.Action == ScriptAction.KeyDown && e.Key == Key.Space)} by {match.State.Players[1]} (join); winner {match.Session.Winner}");
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
                Console.WriteLine($"game over: {match.State.Players[match.Session.Winner ?? 0]} wins");
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
                if (m.Session.Rulings.Count != match.Session.Rulings.Count + 1)
                {
                    continue;
                }
                var r = m.Session.LastRuling!;
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

    // The snooker frame (see the file's head), made in one pass through one game that plays the
    // script as it grows: each turn the planner (centre ball, a person's skill) picks the shot from
    // the table as it stands, and the turn is written as a person plays it, from the D, nominating,
    // aiming, setting the power; after a foul the option the planner would choose is clicked.
    private static List<ScriptEvent> SnookerFrame(int level, ulong seed, int maxShots)
    {
        var live = new LiveGame();
        var planner = new ShotPlanner(live.Physics.Table, live.Physics.Params, live.Physics.Models);
        var skill = SkillLevel.Of(level) with { Spins = 1 };
        int shots = 0, clicks = 0;
        live.CatchUp();
        while (!live.Match.IsOver && shots < maxShots)
        {
            var match = live.Match;
            if (match.PendingOptions.Count > 0)
            {
                var position = new TablePosition(match.Game!.Shots[^1].After, live.Physics.CueBall);
                var option = planner.ChooseOption(match.Session.LastRuling!, position);
                // The option's button, clicked (its key says the same).
                var at = live.Host.World.Menu.CentreOf(option.ToName())!.Value;
                live.Pause(0.4);
                live.Add(new ScriptEvent(0, ScriptAction.MouseMove, Vector: at));
                live.Add(new ScriptEvent(0, ScriptAction.MouseDown, Button: MouseButton.Left));
                live.Add(new ScriptEvent(0, ScriptAction.MouseUp, Button: MouseButton.Left));
                string chooser = match.State.ShooterName;
                live.CatchUp();
                Console.WriteLine($"  {chooser} chooses {option.ToName()}");
                continue;
            }
            var decision = planner.Decide(match.State, TablePosition.Of(live.Physics.Simulation, live.Physics.CueBall), skill, new PlannerBudget(600_000), PlannerRandom.Derive(seed, shots, 0));
            live.Pause(0.3);
            if (decision.Place is { } place && live.Physics.BallInHand)
            {
                PlaceByHand(live, place);
            }
            if (match.NeedsNomination && decision.Call is { IsNomination: true } call)
            {
                // Every other nomination a click on the ball from the view above the table, else B.
                if (clicks++ % 2 == 0)
                {
                    ClickOnBall(live, call.Ball);
                }
                for (int i = 0; i < 22 && match.CurrentNomination?.Ball != call.Ball; i++)
                {
                    live.Press(Key.B);
                    live.CatchUp();
                }
                if (match.CurrentNomination?.Ball != call.Ball)
                {
                    throw new InvalidOperationException($"shot {shots}: could not nominate {call.Ball}");
                }
                live.Press(Key.X);
            }
            else if (decision.Kind != ShotKind.Break)
            {
                live.Press(Key.X);
            }
            live.CatchUp();
            Aim(live, decision.Shot.AimDeg);
            double power = Math.Clamp(Math.Round(decision.Shot.Speed / MatchNode.PowerStep) * MatchNode.PowerStep, MatchNode.MinPower, MatchNode.MaxPower);
            int steps = (int)Math.Round((power - match.Power) / MatchNode.PowerStep);
            for (int i = 0; i < Math.Abs(steps); i++)
            {
                live.Press(steps > 0 ? Key.W : Key.Q);
            }
            live.Press(Key.Space);
            live.Add(new ScriptEvent(0, ScriptAction.WaitRest));
            live.CatchUp();
            shots++;
            var r = match.Session.LastRuling!;
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"shot {shots}: {decision.Kind} {decision.Target} at {power:0.00} m/s: {r.Message}"));
        }
        if (!live.Match.IsOver)
        {
            throw new InvalidOperationException($"the frame did not end in {maxShots} shots");
        }
        var played = live.Match.Game!.Shots;
        var last = played[^1].Ruling;
        Console.WriteLine($"summary: {played.Count} shots, {played.Count(p => p.Ruling.Fouls.Count > 0)} fouls, "
            + $"{played.Count(p => SnookerPart.Of(p.Before).FreeBall)} free balls played, {played.Count(p => p.Ruling.FoulAndMiss)} misses, "
            + $"{played.Count(p => p.Ruling.Fouls.Contains(Foul.CueBallPocketed))} in-offs, {clicks} nominations ({(clicks + 1) / 2} clicked), "
            + $"ends: {(last.Fouls.Count > 0 ? "foul" : "pot")} on {string.Join(",", last.Pocketed)}: {last.Message}");
        return live.Events;
    }

    // The three-cushion game against the computer (see the file's head): on each of Anna's turns
    // a hint (G), waited for, then Space; waiting for rest waits for the computer's whole inning.
    private static List<ScriptEvent> CaromGame(int maxTurns)
    {
        var live = new LiveGame();
        live.CatchUp();
        int turns = 0, seen = 0;
        while (!live.Match.IsOver && turns < maxTurns)
        {
            live.Pause(0.3);
            live.Press(ComputerPlayerNode.HintKey);
            live.Add(new ScriptEvent(0, ScriptAction.WaitRest));
            live.CatchUp();
            if (live.Match.PendingOptions.Count > 0)
            {
                throw new InvalidOperationException($"turn {turns}: an option to choose ({live.Match.Message})");
            }
            live.Pause(0.5);
            live.Press(Key.Space);
            live.Add(new ScriptEvent(0, ScriptAction.WaitRest));
            live.CatchUp();
            turns++;
            var played = live.Match.Game.Shots;
            for (; seen < played.Count; seen++)
            {
                var r = played[seen].Ruling;
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"shot {seen} ({played[seen].Before.ShooterName}): {r.Message}"));
            }
        }
        if (!live.Match.IsOver)
        {
            throw new InvalidOperationException($"the game did not end in {maxTurns} turns");
        }
        return live.Events;
    }

    // Ball in hand: move mode (M), a drag that carries the cue ball to the place (the ball follows
    // the pointer on the bed: the drag is the place's pixel less the ball's in the view drawn), back
    // to the view (V). Not only in the D: with ball in hand the aim keys and the drag do the same anywhere.
    private static void PlaceByHand(LiveGame live, Vec3 place)
    {
        var physics = live.Physics;
        live.Press(Key.M);
        live.CatchUp();
        var (vp, width, height) = live.Host.World.Tree.Root.GetInTree<CameraNode>().CurrentView()!.Value;
        var from = RenderMath.ToPixel(vp, physics.CueBallPosition.ToVector3(), width, height)!.Value;
        var to = RenderMath.ToPixel(vp, place.ToVector3(), width, height)!.Value;
        live.Add(new ScriptEvent(0, ScriptAction.MouseMove, Vector: new Vector2(640, 600)));
        live.Add(new ScriptEvent(0, ScriptAction.MouseDown, Button: MouseButton.Left));
        // One move: a drag in steps could meet a colour on its spot on the way, and stop there.
        live.Add(new ScriptEvent(0, ScriptAction.MouseMoveBy, Vector: to - from));
        live.Add(new ScriptEvent(0, ScriptAction.MouseUp, Button: MouseButton.Left));
        live.Press(Key.V);
        live.CatchUp();
        double off = (physics.CueBallPosition - place).LengthXY;
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  placed in hand {off * 1000:0.000} mm from the plan "));
    }

    // T looks down on the table; a click on the ball nominates it; T again.
    private static void ClickOnBall(LiveGame live, BallId ball)
    {
        live.Press(CameraNode.OverheadKey);
        live.CatchUp();
        var camera = live.Host.World.Tree.Root.GetInTree<CameraNode>();
        var (eye, target) = camera.View(1280, 720);
        var vp = RenderMath.View(eye, target) * RenderMath.Projection(CameraNode.FovYDegrees, 1280f / 720);
        var sim = live.Physics.Simulation;
        var pixel = RenderMath.ToPixel(vp, sim.Balls[sim.IndexOf(ball)].Position.ToVector3(), 1280, 720)!.Value;
        live.Add(new ScriptEvent(0, ScriptAction.MouseMove, Vector: new Vector2(MathF.Round(pixel.X), MathF.Round(pixel.Y))));
        live.Add(new ScriptEvent(0, ScriptAction.MouseDown, Button: MouseButton.Left));
        live.Add(new ScriptEvent(0, ScriptAction.MouseUp, Button: MouseButton.Left));
        live.Press(CameraNode.OverheadKey);
        live.CatchUp();
    }

    // The aim: whole degrees on the keys (Left, Right), the rest by a drag of the view (3 to 4
    // degrees, more than a click's slop), exact to the planner's angle.
    private static void Aim(LiveGame live, double aimDeg)
    {
        var match = live.Match;
        double delta = Math.IEEERemainder(aimDeg - match.AimDegrees, 360);
        int degrees = (int)Math.Floor(delta - 3);
        for (int i = 0; i < Math.Abs(degrees); i++)
        {
            live.Press(degrees > 0 ? Key.Left : Key.Right);
        }
        live.CatchUp();
        double rest = Math.IEEERemainder(aimDeg - match.AimDegrees, 360);
        var camera = live.Host.World.Tree.Root.GetInTree<CameraNode>().Camera;
        float dx = (float)(rest * Math.PI / 180 / OrbitCamera.OrbitRadiansPerPixel / camera.Sensitivity);
        // Over the HUD's band, where no ball is: the drag's press and release are no click on a ball.
        live.Add(new ScriptEvent(0, ScriptAction.MouseMove, Vector: new Vector2(900, 60)));
        live.Add(new ScriptEvent(0, ScriptAction.MouseDown, Button: MouseButton.Left));
        live.Add(new ScriptEvent(0, ScriptAction.MouseMoveBy, Vector: new Vector2(dx / 2, 0)));
        live.Add(new ScriptEvent(0, ScriptAction.MouseMoveBy, Vector: new Vector2(dx - (dx / 2), 0)));
        live.Add(new ScriptEvent(0, ScriptAction.MouseUp, Button: MouseButton.Left));
        live.CatchUp();
        double error = Math.IEEERemainder(aimDeg - match.AimDegrees, 360);
        if (Math.Abs(error) > 1e-3)
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"the aim is {error} deg off the plan"));
        }
    }

    // One game playing a script: a whole one (Run), or one that grows: events are added in the
    // script's future, and the game runs until it has raised them all and rests (CatchUp).
    private sealed class LiveGame
    {
        private readonly double _frame;
        private readonly ManualClock _clock = new();
        private readonly ScriptedInput _scripted;

        public LiveGame(List<ScriptEvent>? events = null, double duration = double.MaxValue, double frameSeconds = 0.05, double speed = SnookerSpeed)
        {
            _frame = frameSeconds;
            Events = events ?? [];
            var scriptClock = new ScriptClock(_clock);
            _scripted = new ScriptedInput(new NoWindow(), new InputScript(Events, duration, speed), scriptClock);
            var match = new MatchSetup(s_rules, s_seats);
            Host = new GameHost(s_scene, SimulationFactory.Create, _scripted, scriptClock, match) { TimeScale = speed };
            if (Host.Tree.Root.FindInTree<ComputerPlayerNode>() is { } computer)
            {
                // As play --script sets it: no search cut short by the clock.
                computer.BudgetMs = 120_000;
            }
            _scripted.IsAtRest = () => Host.IsSettled;
            bool warm = false;
            Host.FrameStarting += now =>
            {
                if (warm)
                {
                    _scripted.Pump(now);
                }
                warm = true;
            };
            Match = Host.Tree.Root.GetInTree<MatchNode>();
            // A script's pixels are on the whole window's view, as play --script frames it.
            Host.Tree.Root.GetInTree<CameraNode>().FramesBelowHud = false;
            // The first frame loads the table (the view turns to the ball on), the second starts the script.
            for (int i = 0; i < 2; i++)
            {
                _clock.Advance(_frame);
                Host.RunFrame();
            }
        }

        public List<ScriptEvent> Events { get; }

        public GameHost Host { get; }

        public MatchNode Match { get; }

        public PhysicsNode Physics => Host.World.Physics;

        private double _next = 0.5;

        // The script's clock now: events go after it.
        private double Now => _clock.Now - (_scripted.Start ?? _clock.Now) - _scripted.Waited;

        public void Pause(double seconds) => _next = Canon(Math.Max(_next, Now + _frame) + seconds);

        public void Add(ScriptEvent e)
        {
            _next = Canon(Math.Max(_next, Now + _frame));
            // As the file will give it back: the game played here is the one the script plays.
            Events.Add(e with { Time = _next, Vector = new Vector2(Canon(e.Vector.X), Canon(e.Vector.Y)) });
            _next = Canon(_next + EventGap);
        }

        public void Press(Key key)
        {
            _next = Canon(Math.Max(_next, Now + _frame));
            Events.Add(new ScriptEvent(_next, ScriptAction.KeyDown, Key: key));
            Add(new ScriptEvent(0, ScriptAction.KeyUp, Key: key));
        }

        private static double Canon(double t) => double.Parse(t.ToString("0.00", CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);

        private static float Canon(float v) => (float)double.Parse(v.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);

        public void CatchUp()
        {
            for (int i = 0; i < 10_000_000 && !(_scripted.CaughtUp && Host.IsSettled); i++)
            {
                _clock.Advance(_frame);
                Host.RunFrame();
            }
        }

        public void RunToTheEnd()
        {
            for (int i = 0; i < 1_000_000 && !_scripted.Finished; i++)
            {
                _clock.Advance(_frame);
                Host.RunFrame();
            }
        }
    }

    private static (MatchNode Match, GameHost Host) Run(List<ScriptEvent> events, double frameSeconds, double speed = Speed)
    {
        var live = new LiveGame(events, (events.Count > 0 ? events[^1].Time : 0) + 0.1, frameSeconds, speed);
        live.RunToTheEnd();
        return (live.Match, live.Host);
    }

    private static List<ScriptEvent> Shot(List<ScriptEvent> prefix, double start, double power, int ballPresses, int aimTweak, (int X, int Y)? drag, bool aimAtGhost, double powerNow)
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
        int steps = (int)Math.Round((power - powerNow) / MatchNode.PowerStep);
        Press(steps > 0 ? Key.W : Key.Q, Math.Abs(steps));
        Press(Key.Space);
        Add(new ScriptEvent(0, ScriptAction.WaitRest));
        return events;
    }

    // The script closes the game tail seconds after its last event (the end of the game on the screen a while).
    private static string ToJson(List<ScriptEvent> events, double speed, double tail)
    {
        var c = CultureInfo.InvariantCulture;
        var sb = new StringBuilder();
        sb.Append(c, $"{{\n  \"format\": \"billiards-input-script/1\",\n  \"speed\": {speed},\n");
        sb.Append(c, $"  \"duration\": {events[^1].Time + tail:0.00},\n  \"events\": [\n");
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
