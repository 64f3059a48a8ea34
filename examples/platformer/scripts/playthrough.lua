-- The play-through: every coin, every enemy shot, the goal, no death. Frames at 1/60 s;
-- each line holds its keys from its first frame to its last.
return {
  frames = 760,
  expect = {coins = "all", kills = "all", deaths = 0, goal = true, drops = 1, coyote = 1,
    buffered = 1},
  input = {
    {1, 309, "right"},
    {105, 119, "jump"},     -- over the first pit, off its edge (coyote time)
    {137, 146, "shoot"},    -- the first enemy, walking back from the ledge
    {199, 212, "jump"},     -- up through the oneway platform, onto it (a coin)
    {221, 238, "jump"},     -- pressed before landing (buffered): onto the wall, and down
    {298, 302, "jump"},     -- a hop onto the first moving platform, waiting at the edge
    {385, 415, "right"},    -- it waits at the far end: over to the second one
    {385, 395, "jump"},
    {405, 470, "shoot"},    -- the two enemies ahead
    {500, 2000, "right"},   -- off the platform, coins, the switch, through the door
    {535, 548, "jump"},     -- onto the oneway ledge (a coin)
    {562, 570, "down"},     -- and down through it
  },
}
