-- Through the first part of the level (the play-through's inputs), past the first
-- checkpoint, then straight into the spikes under the moving platforms: it comes back at
-- the checkpoint, not at the start.
return {
  frames = 360,
  expect = {deaths = 1, causes = "spikes", respawn = 720, goal = false},
  input = {
    {1, 360, "right"},
    {105, 119, "jump"},
    {137, 146, "shoot"},
    {199, 212, "jump"},
    {221, 238, "jump"},
  },
}
