namespace Billiards.Core.Balls;

public sealed partial class BallSet
{
    /// <summary>Id of carom's white ball; the yellow and the red follow it (ids unique across the sets).</summary>
    public const int FirstCarom = 40;

    /// <summary>Diameter of a carom ball (m, UMB: 61.5 mm).</summary>
    public const double CaromDiameter = 0.0615;

    /// <summary>Mass of a carom ball (kg, UMB: 205-220 g; 210 g, rules.md).</summary>
    public const double CaromMass = 0.210;

    /// <summary>
    /// Three-cushion carom (rules.md): the white and the yellow, the two players' cue balls, and
    /// the red, plain balls of 61.5 mm and 210 g; no groups. Which cue ball a player strikes is the
    /// game's (<see cref="Rules.Ruleset.CueBall"/>). Its default physics is played on the heated
    /// cloth (<see cref="Physics.Cloth.Heated"/>).
    /// </summary>
    public static BallSet Carom => Sets.Carom;

    /// <summary>Carom's white ball.</summary>
    public static BallId White { get; } = new(FirstCarom);

    /// <summary>Carom's yellow ball.</summary>
    public static BallId Yellow { get; } = new(FirstCarom + 1);

    /// <summary>Carom's red ball.</summary>
    public static BallId Red { get; } = new(FirstCarom + 2);

    private static BallSet CreateCarom()
    {
        BallKind[] balls =
        [
            new(White, "white", 0, new BallLook(0.96f, 0.95f, 0.90f, false, false)),
            new(Yellow, "yellow", 0, new BallLook(0.97f, 0.80f, 0.12f, false, false)),
            new(Red, "red", 0, new BallLook(0.80f, 0.06f, 0.07f, false, false)),
        ];
        return new BallSet("carom", balls, [White, Yellow], new Dictionary<string, IReadOnlyList<BallId>>(), CaromDiameter / 2, CaromMass)
        {
            Cloth = Physics.Cloth.Heated,
        };
    }
}
