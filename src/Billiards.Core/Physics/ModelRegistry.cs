using Billiards.Core.Physics.Standard;
using Billiards.Core.Physics.Thesis;

namespace Billiards.Core.Physics;

/// <summary>
/// The one registry of physics models: name to model (factory, integrators, ball radius, debug
/// geometry). The only place that turns a model's name into a model.
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
        Find(name) ?? throw new ArgumentException($"unknown model \"{name}\" (expected one of {string.Join(", ", Names.Select(n => $"\"{n}\""))})", nameof(name));
}
