namespace Billiards.Core.Scenes;

/// <summary>
/// A scene or command-line input that cannot be used. Its message is the one line a user sees:
/// the file, the JSON path and what is wrong.
/// </summary>
public sealed class SceneException : Exception
{
    /// <summary>Creates the error for a file and a JSON path.</summary>
    public SceneException(string file, string jsonPath, string problem)
        : base($"{file}: {jsonPath}: {problem}")
    {
        File = file;
        JsonPath = jsonPath;
        Problem = problem;
    }

    /// <summary>The scene file.</summary>
    public string File { get; }

    /// <summary>Where in the file, e.g. <c>$.balls[2].position</c>.</summary>
    public string JsonPath { get; }

    /// <summary>What is wrong.</summary>
    public string Problem { get; }
}
