using Billiards.Core.Physics.Collisions;
using Billiards.Core.Physics.Collisions.BallBall;
using Billiards.Core.Physics.Collisions.BallCushion;
using Billiards.Core.Physics.Collisions.BallPocket;
using Billiards.Core.Physics.Collisions.BallTable;
using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;

namespace Billiards.Core.Physics;

/// <summary>
/// The one registry of physics models: name to model (factory, integrators, ball radius, debug
/// geometry), to integrator, and to the resolver of each interaction (cushion, ball-ball,
/// ball-table, ball-pocket), as
/// pooltool keeps <c>physics/resolve/&lt;interaction&gt;/&lt;model&gt;/</c>. The only place that
/// turns a name into a model, an integrator or a resolver.
/// </summary>
public static class ModelRegistry
{
    /// <summary>The physically based model (physics-standard-model.md), the default.</summary>
    public static PhysicsModel Standard { get; } = new StandardModel();

    /// <summary>The seed's model, kept faithful (thesis-model.md).</summary>
    public static PhysicsModel Thesis { get; } = new ThesisModel();

    /// <summary>The model of a scene that names none.</summary>
    public static PhysicsModel Default => Standard;

    /// <summary>Every model, the default first.</summary>
    public static IReadOnlyList<PhysicsModel> All { get; } = [Standard, Thesis];

    /// <summary>The names of every model, the default first.</summary>
    public static IReadOnlyList<string> Names { get; } = [.. All.Select(m => m.Name)];

    /// <summary>The model called <paramref name="name"/>, or null.</summary>
    public static PhysicsModel? Find(string? name) => All.FirstOrDefault(m => m.Name == name);

    /// <summary>The model called <paramref name="name"/>.</summary>
    /// <exception cref="ArgumentException">For an unknown name.</exception>
    public static PhysicsModel Get(string name) =>
        Find(name) ?? throw new ArgumentException($"unknown model \"{name}\" (expected one of {Quote(Names)})", nameof(name));

    /// <summary>The standard model's exact integrator (its default).</summary>
    public static IIntegrator Exact { get; } = Standard.Integrators[0];

    /// <summary>The standard model's explicit Euler integrator.</summary>
    public static IIntegrator Euler { get; } = Standard.Integrators[1];

    /// <summary>The standard model's event-based reference solver.</summary>
    public static IIntegrator Event { get; } = Standard.Integrators[2];

    /// <summary>The names of <paramref name="model"/>'s integrators, its default first.</summary>
    public static IReadOnlyList<string> IntegratorNames(PhysicsModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        return [.. model.Integrators.Select(i => i.Name)];
    }

    /// <summary><paramref name="model"/>'s integrator called <paramref name="name"/>, or null.</summary>
    public static IIntegrator? FindIntegrator(PhysicsModel model, string? name)
    {
        ArgumentNullException.ThrowIfNull(model);
        return model.Integrators.FirstOrDefault(i => i.Name == name);
    }

    /// <summary>Every ball-cushion resolver, the default first.</summary>
    public static IReadOnlyList<IBallCushionModel> BallCushionModels { get; } =
        [Han2005.Instance, Mathavan2010.Instance, StrongeCompliant.Instance];

    /// <summary>Every ball-ball resolver, the default first.</summary>
    public static IReadOnlyList<IBallBallModel> BallBallModels { get; } =
        [FrictionalInelastic.Instance, FrictionalMathavan.Instance];

    /// <summary>Every ball-table resolver (landings on the bed and on a rail's top), the default first.</summary>
    public static IReadOnlyList<IBallTableModel> BallTableModels { get; } = [FrictionalLanding.Instance];

    /// <summary>Every ball-pocket resolver (a ball dropping into a hole), the default first.</summary>
    public static IReadOnlyList<IBallPocketModel> BallPocketModels { get; } = [CanonicalPocket.Instance];

    /// <summary>The names of <see cref="BallCushionModels"/>.</summary>
    public static IReadOnlyList<string> BallCushionNames { get; } = [.. BallCushionModels.Select(m => m.Name)];

    /// <summary>The names of <see cref="BallBallModels"/>.</summary>
    public static IReadOnlyList<string> BallBallNames { get; } = [.. BallBallModels.Select(m => m.Name)];

    /// <summary>The names of <see cref="BallTableModels"/>.</summary>
    public static IReadOnlyList<string> BallTableNames { get; } = [.. BallTableModels.Select(m => m.Name)];

    /// <summary>The names of <see cref="BallPocketModels"/>.</summary>
    public static IReadOnlyList<string> BallPocketNames { get; } = [.. BallPocketModels.Select(m => m.Name)];

    /// <summary>The ball-table resolver called <paramref name="name"/>, or null.</summary>
    public static IBallTableModel? FindBallTable(string? name) => BallTableModels.FirstOrDefault(m => m.Name == name);

    /// <summary>The ball-pocket resolver called <paramref name="name"/>, or null.</summary>
    public static IBallPocketModel? FindBallPocket(string? name) => BallPocketModels.FirstOrDefault(m => m.Name == name);

    /// <summary>The ball-cushion resolver called <paramref name="name"/>, or null.</summary>
    public static IBallCushionModel? FindBallCushion(string? name) => BallCushionModels.FirstOrDefault(m => m.Name == name);

    /// <summary>The ball-ball resolver called <paramref name="name"/>, or null.</summary>
    public static IBallBallModel? FindBallBall(string? name) => BallBallModels.FirstOrDefault(m => m.Name == name);

    /// <summary>Names in double quotes, comma-separated, for error messages.</summary>
    public static string Quote(IEnumerable<string> names) => string.Join(", ", names.Select(n => $"\"{n}\""));
}
