using System.Numerics;
using Billiards.Core.Mathematics;

namespace Billiards.Core.Physics.Thesis;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// A copy of the engine's per-run state: every ball, the clock, the shot's bookkeeping, the
    /// cue's effet (tip offset and elevation) and the random source of the end-of-shot reset.
    /// </summary>
    internal sealed class State
    {
        public State(int n)
        {
            Positions = new Vector3[n];
            Velocities = new Vector3[n];
            Orientations = new Quaternion[n];
            Pockets = new int[n];
            Pocketed = new bool[n];
            StartPositions = new Vector3[n];
        }

        public Vector3[] Positions { get; }
        public Vector3[] Velocities { get; }
        public Quaternion[] Orientations { get; }
        public int[] Pockets { get; }
        public bool[] Pocketed { get; }
        public Vector3[] StartPositions { get; }
        public long Steps { get; set; }
        public bool IsAtRest { get; set; }
        public ShotEnd LastShotEnd { get; set; }
        public Vector3 LastCueDisplacement { get; set; }
        public Vector3 CueShotStart { get; set; }
        public float EX { get; set; }
        public float EY { get; set; }
        public float Grade { get; set; }
        public SeededRandom Random { get; } = new(0);
    }

    /// <summary>A state sized for this engine's balls (nothing copied yet).</summary>
    /// <exception cref="InvalidOperationException">The engine's random source is not a <see cref="SeededRandom"/>, whose state can be copied.</exception>
    internal State CreateState()
    {
        if (_random is not SeededRandom)
        {
            throw new InvalidOperationException("the engine's random source must be a SeededRandom for its state to be saved");
        }
        return new State(_balls.Length);
    }

    /// <summary>Copies the per-run state into <paramref name="state"/>; allocates nothing.</summary>
    internal void Save(State state)
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            var ball = _balls[i];
            state.Positions[i] = ball.Position;
            state.Velocities[i] = ball.Velocity;
            state.Orientations[i] = ball.Orientation;
            state.Pockets[i] = ball.Pocket;
            state.Pocketed[i] = ball.IsPocketed;
        }
        _startPositions.CopyTo(state.StartPositions, 0);
        state.Steps = Steps;
        state.IsAtRest = IsAtRest;
        state.LastShotEnd = LastShotEnd;
        state.LastCueDisplacement = LastCueDisplacement;
        state.CueShotStart = _cueShotStart;
        state.EX = Queue.EX;
        state.EY = Queue.EY;
        state.Grade = Queue.Grade;
        state.Random.CopyFrom((SeededRandom)_random);
    }

    /// <summary>Puts the per-run state of <paramref name="state"/> back; allocates nothing.</summary>
    internal void Load(State state)
    {
        for (int i = 0; i < _balls.Length; i++)
        {
            var ball = _balls[i];
            ball.Position = state.Positions[i];
            ball.Velocity = state.Velocities[i];
            ball.Orientation = state.Orientations[i];
            ball.Pocket = state.Pockets[i];
            ball.IsPocketed = state.Pocketed[i];
        }
        state.StartPositions.CopyTo(_startPositions, 0);
        Steps = state.Steps;
        IsAtRest = state.IsAtRest;
        LastShotEnd = state.LastShotEnd;
        LastCueDisplacement = state.LastCueDisplacement;
        _cueShotStart = state.CueShotStart;
        Queue.EX = state.EX;
        Queue.EY = state.EY;
        Queue.Grade = state.Grade;
        ((SeededRandom)_random).CopyFrom(state.Random);
    }
}
