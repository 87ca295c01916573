using System.Globalization;
using Billiards.Core.Balls;
using Billiards.Core.Physics;
using Billiards.Core.Scenes;

// A scene: the 1 straight in to the foot-left pocket. SceneLoader.Load("shot.json") reads a file.
const string Json = """
    {
      "format": "billiards-scene/1",
      "table": { "preset": "pool-9ft" },
      "balls": [ { "id": "cue", "position": [0.0, 0.0] }, { "id": "1", "position": [0.6, 0.3] } ],
      "shot": { "speed": 2.0, "aim_deg": 26.565, "tip": [0.0, -0.3], "elevation_deg": 0.0 }
    }
    """;
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
Scene scene = SceneLoader.Parse(Json, "straight-in.json");

// Strike the shot and run until every ball rests (standard model, exact collision times).
Simulation sim = SimulationRunner.Run(scene, new RunOptions()).Simulation;

foreach (SimEvent e in sim.Events.AsSpan())
{
    string what = e.Kind switch
    {
        EventKind.BallBall => $"{e.A} hits {e.B}",
        EventKind.BallCushion or EventKind.BallPocket => $"{e.A} at {sim.FeatureName(e.Kind, e.Feature)}",
        _ => $"{e.A} struck",
    };
    Console.WriteLine($"{e.Time:0.000} s  {e.Kind,-11} {what}, {e.Speed:0.00} m/s");
}
Console.WriteLine($"at rest at {sim.Time:0.000} s:");
for (int i = 0; i < sim.Ids.Count; i++)
{
    BallState ball = sim.Balls[i];
    Console.WriteLine($"  {sim.Ids[i],-4} {ball.State,-10} ({ball.Position.X:0.000}, {ball.Position.Y:0.000}) m");
}
