using Billiards.Core.Balls;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Rules;

/// <summary>
/// Practice: the turn controller's timeline without a referee. Every shot is legal and the player
/// stays at the table; the balls that drop stay down, and a cue ball that drops (or leaves the
/// table) comes back in hand anywhere on the table. The game never ends. It is no game of the
/// registry (<see cref="Ruleset.All"/> does not list it, and scenes, records and <c>--rules</c> do
/// not name it): <see cref="Session.Practice"/> plays it on any table with any balls.
/// </summary>
public sealed class PracticeRuleset : Ruleset
{
    private PracticeRuleset()
    {
    }

    /// <summary>The one practice ruleset.</summary>
    public static PracticeRuleset Instance { get; } = new();

    /// <summary>Practice's name ("practice").</summary>
    public static GameRules Practice { get; } = new("practice");

    /// <inheritdoc />
    public override GameRules Game => Practice;

    /// <inheritdoc />
    public override string ShortName => "practice";

    /// <inheritdoc />
    public override string Title => "Practice";

    /// <summary>None: practice starts from a position, never from a rack.</summary>
    public override IReadOnlyList<BallId> Balls => [];

    /// <inheritdoc />
    public override BallInHand BreakBallInHand => BallInHand.None;

    /// <inheritdoc />
    public override bool CallsShots => false;

    /// <inheritdoc />
    public override bool HasThreeFouls => false;

    /// <inheritdoc />
    public override bool HasComputerPlayer => false;

    /// <inheritdoc />
    public override bool PowerBreak => false;

    /// <summary>No bound: practice goes on as long as the player likes.</summary>
    public override int MaxShots(GameState start) => int.MaxValue;

    /// <summary>A dropped cue ball comes back on the head spot when the player strikes without placing it.</summary>
    public override Vec3 CueStart(TableSpec table, double ballRadius) => Initializer.HeadSpot(table, ballRadius);

    /// <inheritdoc />
    public override IReferee Referee(TableSpec table, double ballRadius) => new PracticeReferee(table, ballRadius);

    /// <summary>Every object ball.</summary>
    public override IReadOnlyList<BallId> LegalTargets(GameState state, IEnumerable<BallId> objectBalls) => [.. objectBalls];

    /// <inheritdoc />
    public override HudTarget Target(GameState state, int player, IReadOnlyCollection<BallId> objectBalls) => new("practice", []);

    // Notes the shot and hands the table back to the same player.
    private sealed class PracticeReferee(TableSpec table, double ballRadius) : IReferee
    {
        public GameRules Rules => Practice;

        public TableSpec Table { get; } = table;

        public double BallRadius { get; } = ballRadius;

        public Ruling Judge(GameState before, ShotRecord shot)
        {
            ArgumentNullException.ThrowIfNull(before);
            ArgumentNullException.ThrowIfNull(shot);
            // The shot starts from the balls on the table: whatever is out of play after it dropped on it.
            var pocketed = new List<BallId>();
            foreach (var id in shot.Ids)
            {
                if (id != shot.CueBall && shot.After(id).IsOutOfPlay)
                {
                    pocketed.Add(id);
                }
            }
            bool scratch = shot.After(shot.CueBall).IsOutOfPlay;
            var hand = scratch ? BallInHand.Table : BallInHand.None;
            string message = scratch ? "The cue ball dropped: place it anywhere on the table."
                : pocketed.Count switch { 0 => "Nothing dropped.", 1 => "One ball dropped.", int n => $"{n} balls dropped." };
            var next = before with { Shot = before.Shot + 1, Call = null, PushOut = false, Placement = null, BallInHand = hand };
            return new Ruling(true, [], pocketed, true, hand, [], [], false, null, message, next);
        }
    }
}
