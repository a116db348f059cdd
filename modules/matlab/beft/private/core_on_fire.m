function [core, again] = core_on_fire(core, fire)
% Takes a FIRE token: again is the DONE to send once more (a FIRE of the
% firing last run, or of the same transition and tick under a new id after
% a successful firing: an arbiter restarted), else []. An older FIRE is
% dropped; a newer one replaces a firing that has not run yet.
  again = [];
  if ~strcmp(fire.expert, core.name)
    return;
  end
  id = fire.firing_id;
  pending = core.pending;
  if ~isempty(pending) && pending.firing_id >= id
    if pending.firing_id == id && core.pending_fired
      again = core.last_done;
    elseif id < pending.firing_id
      say(core.name, 'dropped stale FIRE %d (already at %d)', id, pending.firing_id);
    end
    return;
  end
  if repeats_the_firing_done(core, fire)
    core.pending.firing_id = id;
    core.last_fired_id = id;
    core.last_done.firing_id = id;
    again = core.last_done;
    return;
  end
  if ~isempty(pending) && ~core.pending_fired
    say(core.name, 'FIRE %d superseded by %d before it ran', pending.firing_id, id);
  end
  core.pending = firing_of(fire);
  core.pending_fired = false;
  core.firing = true;
  core.pending_since = tic;
end

function yes = repeats_the_firing_done(core, fire)
  yes = ~isempty(core.pending) && core.pending_fired && ~isempty(core.last_done) && ...
        core.last_done.outcome == 0 && core.last_done.firing_id == core.pending.firing_id && ...
        core.pending.tick == fire.tick && strcmp(core.pending.transition, fire.transition);
end
