using Billiards.Core.Balls;
using Billiards.Core.Cue;
using Billiards.Core.Mathematics;
using Billiards.Core.Physics;
using Billiards.Core.Physics.Collisions;
using Billiards.Core.Setup;
using Billiards.Core.Table;

namespace Billiards.Core.Scenes;

/// <summary>The physics a scene asks for.</summary>
/// <param name="Model">The model (<see cref="ModelRegistry"/>; the standard model by default).</param>
/// <param name="Integrator">One of the model's <see cref="PhysicsModel.Integrators"/>.</param>
/// <param name="Dt">Fixed step (s); default 1/250.</param>
/// <param name="Params">Parameters of the standard model (the thesis model keeps its own constants).</param>
public sealed record PhysicsConfig(PhysicsModel Model, IIntegrator Integrator, double Dt, PhysicsParams Params)
{
    /// <summary>The resolver of each interaction (<c>physics.models</c>; the standard model's only).</summary>
    public InteractionModels Models { get; init; } = InteractionModels.Default;

    /// <summary>The default step, 1/250 s (the seed's rate).</summary>
    public const double DefaultDt = 1.0 / 250.0;

    /// <summary>The standard model with the exact integrator at 1/250 s and default parameters.</summary>
    public static PhysicsConfig Default { get; } = new(ModelRegistry.Default, ModelRegistry.Default.Integrators[0], DefaultDt, PhysicsParams.Default);
}

/// <summary>
/// The names scenes give the integrators. The integrators themselves are types, which a model lists
/// (<see cref="PhysicsModel.Integrators"/>) and <see cref="ModelRegistry"/> finds by name.
/// </summary>
public static class Integrators
{
    /// <summary>Closed-form motion with exact collision times inside fixed steps.</summary>
    public const string Exact = "exact";
    /// <summary>Naive explicit Euler with overlap detection: the accuracy report's baseline.</summary>
    public const string Euler = "euler";
    /// <summary>Event-based reference solver.</summary>
    public const string Event = "event";
    /// <summary>The thesis model's own fixed step with overlap detection.</summary>
    public const string Fixed = "fixed";
}

/// <summary>A ball's initial state as the scene (or its rack) places it.</summary>
/// <param name="Id">Which ball.</param>
/// <param name="Position">Centre (m), z = R.</param>
/// <param name="Velocity">Initial velocity (m/s), in the bed plane.</param>
/// <param name="Spin">Initial angular velocity (rad/s).</param>
public sealed record BallSetup(BallId Id, Vec3 Position, Vec3 Velocity, Vec3 Spin);

/// <summary>
/// A loaded and validated scene: the table, the physics, the balls (the rack merged with the
/// explicit balls, sorted by id), an optional shot and rules. A scene asks only for what it needs.
/// </summary>
public sealed record Scene(
    string Path,
    string? Name,
    TableSpec Table,
    PhysicsConfig Physics,
    RackSpec? Rack,
    IReadOnlyList<BallSetup> Balls,
    ShotSpec? Shot,
    string? Rules)
{
    /// <summary>
    /// The state of a game before the scene's shot (the "game" block), or null. A scene with a
    /// game block and no shot is a position: <c>suggest</c> plays it, <c>simulate</c> refuses it.
    /// </summary>
    public Rules.GameState? Game { get; init; }

    /// <summary>
    /// Which game the scene is played as (<see cref="SceneGame.Of(Scene)"/>): its game block's
    /// rules, else its "rules"; null for a scene of no game (practice).
    /// </summary>
    public global::Billiards.Core.Rules.GameRules? PlayedAs => SceneGame.Of(this);

    /// <summary>The balls the scene is played with: its game's set, pool's without a game.</summary>
    public BallSet BallSet { get; init; } = BallSet.Pool;

    /// <summary>The ball the scene's shot strikes: the game's cue ball for its shooter, else the set's first cue ball.</summary>
    public BallId CueBall => Game is { } game ? global::Billiards.Core.Rules.Ruleset.For(game.Rules).CueBall(game) : BallSet.CueBalls[0];

    /// <summary>The ball radius the scene's model uses (m).</summary>
    public double BallRadius => Physics.Model.BallRadius(Physics.Params);

    /// <summary>Where the scene's balls start, in the scene's order.</summary>
    public BallLayout Layout => new(Balls.Select(b => (b.Id, b.Position)));

    /// <summary>A scene of <paramref name="balls"/> at rest, in the layout's order: a game's position between shots, or a shot's start.</summary>
    /// <param name="balls">The balls and their centres.</param>
    /// <param name="table">The table.</param>
    /// <param name="physics">The physics.</param>
    /// <param name="ballSet">The balls' set.</param>
    /// <param name="shot">The shot to strike, or null.</param>
    /// <param name="rules">The rules' name, or null.</param>
    public static Scene Of(BallLayout balls, TableSpec table, PhysicsConfig physics, BallSet ballSet, ShotSpec? shot = null, string? rules = null)
    {
        ArgumentNullException.ThrowIfNull(balls);
        return new("game", null, table, physics, null, [.. balls.Select(b => new BallSetup(b.Id, b.Position, Vec3.Zero, Vec3.Zero))], shot, rules) { BallSet = ballSet };
    }
}

/// <summary>Constants of the thesis model that the rest of Core needs in SI.</summary>
public static class ThesisConstants
{
    /// <summary>The seed's ball radius, 2.86 cm, in metres.</summary>
    public const double RadiusMetres = 0.0286;
}
