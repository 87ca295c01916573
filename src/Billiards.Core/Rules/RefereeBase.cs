using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// What the five referees share: checking the shot belongs to their game, reading the shot's
/// facts, the fouls common to the pool games, the fouls-in-row count, and assembling the ruling
/// and the next state. Each game's rules are one hook, <see cref="Rule"/>.
/// </summary>
internal abstract class RefereeBase(GameRules rules, TableSpec table, double ballRadius) : IReferee
{
    public GameRules Rules { get; } = rules;

    /// <summary>The ruleset of the game judged.</summary>
    protected Ruleset Ruleset => Ruleset.For(Rules);

    public TableSpec Table { get; } = table;

    public double BallRadius { get; } = ballRadius;

    /// <summary>
    /// False for a referee that rules without words (the planner's search, which judges thousands
    /// of shots and reads none of their sentences): its rulings' <see cref="Ruling.Message"/> is empty.
    /// </summary>
    internal bool Words { get; set; } = true;

    public Ruling Judge(GameState before, ShotRecord shot)
    {
        ArgumentNullException.ThrowIfNull(before);
        ArgumentNullException.ThrowIfNull(shot);
        if (before.Rules != Rules)
        {
            throw new ArgumentException($"a {Rules.ToName()} referee cannot judge a {before.Rules.ToName()} game", nameof(before));
        }
        var facts = new ShotFacts(before, shot, Table, BallRadius);
        return Rule(before, shot, facts, new RulingBuilder(before, facts) { Words = Words });
    }

    /// <summary>
    /// The game's rules on one shot: fill <paramref name="ruling"/> from <paramref name="facts"/>
    /// and return what it builds. <paramref name="shot"/> is there for the games whose rules read
    /// more than the facts (snooker: the balls' positions before the shot, the cue ball's flight),
    /// and a game may add to the built ruling (snooker's points, penalty and next ball on).
    /// </summary>
    protected abstract Ruling Rule(GameState before, ShotRecord shot, ShotFacts facts, RulingBuilder ruling);

    /// <summary>
    /// The fouls common to all games (rules.md): scratch, no contact, wrong ball first (when
    /// <paramref name="isTarget"/> is given), no rail after a legal first contact.
    /// </summary>
    protected static void CommonFouls(ShotFacts facts, RulingBuilder ruling, Func<BallId, bool>? isTarget)
    {
        if (facts.Scratch)
        {
            ruling.Foul(Foul.CueBallPocketed);
        }
        OffTableFoul(facts, ruling);
        if (facts.FirstContact is not { } first)
        {
            ruling.Foul(Foul.NoContact);
            return;
        }
        if (isTarget is not null && !isTarget(first))
        {
            ruling.Foul(Foul.WrongBallFirst);
            return;
        }
        if (!facts.RailAfterContact)
        {
            ruling.Foul(Foul.NoRail);
        }
    }

    /// <summary>The <c>ball-off-table</c> foul, when a ball (cue or object) left the table over a rail.</summary>
    protected static void OffTableFoul(ShotFacts facts, RulingBuilder ruling)
    {
        if (facts.CueOffTable || facts.OffTable.Count > 0)
        {
            ruling.Foul(Foul.BallOffTable);
        }
    }

}

/// <summary>Collects a ruling while a referee works through a shot; <see cref="Build"/> makes it.</summary>
internal sealed class RulingBuilder(GameState before, ShotFacts facts)
{
    private readonly List<Foul> _fouls = [];
    private readonly BallNumbers _spot = new(0);
    private readonly List<string> _reasons = [];

    public GameState Before { get; } = before;

    /// <summary>The shooter stays at the table (only when legal).</summary>
    public bool Continue { get; set; }

    /// <summary>Ball in hand for the next shooter.</summary>
    public BallInHand BallInHand { get; set; }

    public List<RefereeOption> Options { get; } = [];

    public bool GameOver { get; private set; }

    public int? Winner { get; private set; }

    /// <summary>The game's own part of the state after the shot (8-ball's groups).</summary>
    public GameStatePart? Part { get; set; } = before.Part;

    /// <summary>The score after the shot.</summary>
    public PerPlayer<int> Score { get; set; } = before.Score;

    /// <summary>The fouls in a row after the shot; set by <see cref="CountFouls"/>.</summary>
    public PerPlayer<int> FoulsInRow { get; set; } = before.FoulsInRow;

    /// <summary>The shot's last word, in place of the default "X is at the table".</summary>
    public string? Outcome { get; set; }

    /// <summary>False when the ruling is built without its sentence (<see cref="RefereeBase.Words"/>).</summary>
    public bool Words { get; init; } = true;

    /// <summary>An extra sentence after the outcome (a warning).</summary>
    public string? Note { get; set; }

    /// <summary>
    /// What the shot scored, in place of the default sentence of the balls potted ("The break pots
    /// the 3 and the 11."): snooker's points ("4 points to Anna.", "Anna pots a red: 1 point.").
    /// </summary>
    public string? Scored { get; set; }

    public List<BallId> Rerack { get; } = [];

    public bool Legal => _fouls.Count == 0;

    public int FoulCount => _fouls.Count;

    public bool Has(Foul foul) => _fouls.Contains(foul);

    public void Foul(Foul foul, string? reason = null)
    {
        if (!_fouls.Contains(foul))
        {
            _fouls.Add(foul);
            _reasons.Add(reason ?? Reason(foul));
        }
    }

    public void SpotBall(BallId ball) => _spot.Add(ball.Value);

    public void Win(int player, string outcome)
    {
        GameOver = true;
        Winner = player;
        Outcome = outcome;
    }

    /// <summary>Counts the shot in the shooter's fouls in a row: one more after a foul, none after a legal shot.</summary>
    public void CountFouls()
    {
        int shooter = Before.Shooter;
        FoulsInRow = FoulsInRow.With(shooter, Legal ? 0 : FoulsInRow[shooter] + 1);
    }

    public Ruling Build()
    {
        var b = Before;
        bool cont = Continue && Legal && !GameOver;
        int nextShooter = cont ? b.Shooter : b.Incoming;
        var next = GameOver
            ? new GameState(b.Rules) { Players = b.Players, Shooter = Winner ?? b.Shooter, Target = b.Target }
            : b with
            {
                Shooter = nextShooter,
                Shot = b.Shot + 1,
                Part = Part,
                Call = null,
                PushOut = false,
                FoulsInRow = FoulsInRow,
                Score = Score,
                BallInHand = BallInHand,
                Placement = null,
            };
        return new Ruling(
            Legal,
            [.. _fouls],
            [.. facts.Pocketed],
            cont,
            GameOver ? BallInHand.None : BallInHand,
            [.. _spot.Select(n => new BallId(n))],
            GameOver ? [] : [.. Options],
            GameOver,
            Winner,
            Words ? Message(cont, nextShooter) : "",
            next)
        {
            Rerack = [.. Rerack],
            Score = Score,
        };
    }

    private string Message(bool cont, int nextShooter)
    {
        var b = Before;
        string next = b.Players[nextShooter];
        var text = new List<string>();
        if (!Legal)
        {
            text.Add($"Foul by {b.ShooterName}: {string.Join(" and ", _reasons)}.");
        }
        if (Scored is not null)
        {
            text.Add(Scored);
        }
        else if (Legal && !GameOver && facts.Pocketed.Count > 0)
        {
            // Which balls went down, in a player's words; a pot that is not the call says what was called.
            string who = b.Shot == 0 ? "The break" : b.ShooterName;
            string called = !cont && b.Call is { IsSafety: false } call && call.Ball != BallId.None && !facts.Pocketed.Contains(call.Ball) ? $" (the {call.Ball} was called)" : "";
            text.Add($"{who} pots {Balls(facts.Pocketed)}{called}.");
        }
        if (Outcome is not null)
        {
            text.Add(Outcome);
        }
        else if (cont)
        {
            text.Add($"{b.ShooterName} shoots again.");
        }
        else if (BallInHand != BallInHand.None)
        {
            text.Add(BallInHand == BallInHand.Kitchen ? $"{next} has ball in hand behind the head string." : $"{next} has ball in hand.");
        }
        else
        {
            text.Add($"{next} is at the table.");
        }
        if (Options.Count > 0 && !GameOver)
        {
            text.Add($"{next} chooses: {string.Join(" or ", Options.Select(Ruleset.For(b.Rules).WordOf))}.");
        }
        if (Note is not null)
        {
            text.Add(Note);
        }
        return string.Join(" ", text);
    }

    /// <summary>"the 3", "the 3 and the 11", "the 3, the 5 and the 11".</summary>
    public static string Balls(IReadOnlyList<BallId> balls)
    {
        ArgumentNullException.ThrowIfNull(balls);
        var names = balls.Select(x => $"the {x}").ToList();
        return names.Count <= 1 ? string.Concat(names) : $"{string.Join(", ", names.Take(names.Count - 1))} and {names[^1]}";
    }

    private string Reason(Foul foul) => foul switch
    {
        Rules.Foul.BadPlacement => "the cue ball was placed outside its region or on a ball",
        Rules.Foul.CueBallPocketed => "the cue ball was pocketed",
        Rules.Foul.NoContact => "the cue ball touched no object ball",
        Rules.Foul.WrongBallFirst => string.Create(CultureInfo.InvariantCulture, $"the cue ball first touched the {facts.FirstContact}, not a legal target"),
        Rules.Foul.NoRail => "no ball reached a cushion after the contact",
        Rules.Foul.BadBreak => "the break was not legal",
        Rules.Foul.EightBallEarly => "the 8 was pocketed before the group was cleared",
        Rules.Foul.EightBallFoul => "the 8 was pocketed on a foul",
        Rules.Foul.EightBallUncalled => "the 8 went into a pocket that was not called",
        Rules.Foul.ThreeFouls => "three fouls in a row",
        Rules.Foul.BallOffTable => facts.CueOffTable ? "the cue ball left the table" : "a ball left the table",
        Rules.Foul.EightBallOffTable => "the 8 left the table",
        _ => foul.ToName(),
    };
}
