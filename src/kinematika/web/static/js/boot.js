// Which page a link opens: the exercise mode (`#exercise=1&…`, a link of `kinematika exercise`'s
// links.txt; js/exercise.js) or the builder (js/main.js). In the exercise mode the builder is
// never started: its editor, its answers and its requests (it loads the linked model and
// solves it) would show a student the key, so only the exercise's script runs.
const exercise = new URLSearchParams(location.hash.replace(/^#/, "")).has("exercise");
await import(exercise ? "./exercise.js" : "./main.js");
