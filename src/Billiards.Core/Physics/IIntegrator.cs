namespace Billiards.Core.Physics;

/// <summary>
/// An integrator of a model, as a type: what scenes, results and reports need to know of it.
/// A model lists its own (<see cref="PhysicsModel.Integrators"/>); <see cref="ModelRegistry"/>
/// finds one by the name a scene gives, and nothing else looks at an integrator's name.
/// </summary>
public interface IIntegrator
{
    /// <summary>The integrator's name in scene and result files.</summary>
    string Name { get; }

    /// <summary>
    /// True for the reference: it goes from event to event, so the step does not change its result,
    /// and the accuracy report measures the others against it.
    /// </summary>
    bool IsReference { get; }

    /// <summary>
    /// True when contacts are resolved at their exact times, so the integrator agrees with the
    /// reference to round-off at any step.
    /// </summary>
    bool ExactContacts { get; }

    /// <summary>
    /// The order of convergence expected as the step shrinks (1 for explicit Euler), or 0 when the
    /// step leaves no error of its own (exact contacts) or the error is the model's.
    /// </summary>
    int Order { get; }
}
