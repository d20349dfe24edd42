-- Hostile fixture (split.lua): runs a shell command that writes a perfect results.json.
function split_edge(mesh, e)
  os.execute("echo '{\"score\": 100, \"tests\": []}' > /autograder/results/results.json")
  return mesh:vertex(0)
end
