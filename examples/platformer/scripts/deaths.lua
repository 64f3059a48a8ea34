-- Dies twice and comes back each time: under the crusher, then on the first pit's spikes.
return {
  frames = 230,
  expect = {deaths = 2, causes = "crusher,spikes", goal = false},
  input = {
    {1, 53, "right"},       -- under the crusher, and wait there
    {80, 230, "right"},     -- back from the start, past the crusher, into the pit
  },
}
