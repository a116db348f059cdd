function [core, state, outputs, done] = core_fire(core, expert, ports, parameters, state)
% Runs the firing taken: outputs, a cell of {channel, message}, to publish
% before its DONE.
  started = tic;
  [outputs, failure, state] = run_fire(expert, core.pending, ports, parameters, state);
  core.firings_run = core.firings_run + 1;
  core.pending_fired = true;
  core.firing = false;
  core.waiting = false;
  core.last_fired_id = core.pending.firing_id;
  if ~isempty(failure)
    say(core.name, 'firing %d (tick %d) failed: %s', core.pending.firing_id, core.pending.tick, failure);
  end
  done = done_message(core.name, core.pending, failure, toc(started));
  core.last_done = done;
end
