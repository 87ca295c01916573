using Billiards.App.Input;
using Billiards.App.Nodes;
using Billiards.App.Platform;
using Billiards.Core.Table;

namespace Billiards.App.Tests.Nodes;

public class NodeTests
{
    private sealed class Probe(string name, List<string> log, bool handles = false) : Node(name)
    {
        protected override void Ready() => log.Add($"ready {Name}");

        protected override void Process(double dt) => log.Add($"process {Name}");

        protected override void PhysicsProcess(double dt) => log.Add($"physics {Name}");

        protected override bool Input(InputEvent e)
        {
            log.Add($"input {Name}");
            return handles;
        }

        protected override void Draw(FrameBuilder frame) => log.Add($"draw {Name}");
    }

    private sealed class Marker : Node;

    private static (SceneTree Tree, List<string> Log) Tree(bool bHandles = false)
    {
        // root
        //  +- a
        //  |   +- a1
        //  +- b
        var log = new List<string>();
        var root = new Probe("root", log);
        var a = root.AddChild(new Probe("a", log));
        a.AddChild(new Probe("a1", log));
        root.AddChild(new Probe("b", log, bHandles));
        return (new SceneTree(root), log);
    }

    [Fact]
    public void ReadyRunsChildrenBeforeParents()
    {
        var (tree, log) = Tree();
        tree.Start();
        Assert.Equal(["ready a1", "ready a", "ready b", "ready root"], log);
        Assert.Throws<InvalidOperationException>(tree.Start);
    }

    [Fact]
    public void ProcessPhysicsAndDrawRunParentsFirstInChildOrder()
    {
        var (tree, log) = Tree();
        tree.Start();
        log.Clear();
        tree.Process(0.016);
        tree.PhysicsProcess(0.004);
        tree.Draw(new FrameBuilder(TableSpec.FromPreset("pool-9ft"), 10, 10, 0));
        Assert.Equal(
            ["process root", "process a", "process a1", "process b",
             "physics root", "physics a", "physics a1", "physics b",
             "draw root", "draw a", "draw a1", "draw b"], log);
    }

    [Fact]
    public void InputRunsFromTheLastChildBackAndStopsWhereHandled()
    {
        var (tree, log) = Tree();
        tree.Start();
        log.Clear();
        Assert.False(tree.Input(new KeyInput(0, Key.A, true)));
        Assert.Equal(["input b", "input a1", "input a", "input root"], log);

        var (handled, log2) = Tree(bHandles: true);
        handled.Start();
        log2.Clear();
        Assert.True(handled.Input(new KeyInput(0, Key.A, true)));
        Assert.Equal(["input b"], log2);
    }

    [Fact]
    public void AChildAddedToAStartedTreeGetsReadyAtOnceAndSignalsIt()
    {
        var (tree, log) = Tree();
        tree.Start();
        log.Clear();
        var c = new Probe("c", log);
        Node? signalled = null;
        c.Readied += n => signalled = n;
        tree.Root.AddChild(c);
        Assert.Equal(["ready c"], log);
        Assert.Same(c, signalled);
        Assert.Same(tree, c.Tree);
    }

    [Fact]
    public void ChildrenCanBeRemovedAndFoundAndCyclesAreRefused()
    {
        var (tree, _) = Tree();
        var a = tree.Root.Children[0];
        var a1 = a.Children[0];
        var marker = a1.AddChild(new Marker());
        Assert.Same(marker, tree.Root.Find<Marker>());
        Assert.Same(marker, tree.Root.Children[1].FindInTree<Marker>()); // from a sibling's subtree
        Assert.Null(a.Find<SceneTree>());
        Assert.Throws<InvalidOperationException>(() => a1.AddChild(a));
        Assert.Throws<InvalidOperationException>(() => tree.Root.AddChild(a1)); // already has a parent
        a.RemoveChild(a1);
        Assert.Null(a1.Parent);
        Assert.Null(a1.Tree);
        Assert.Empty(a.Children);
        Assert.Throws<InvalidOperationException>(() => a.RemoveChild(a1));
    }
}
