function [core, ports, state] = resume_from_history(core, expert, history, ports, parameters, state)
% A restarted expert rebuilds its state from the run's history (cell of
% {channel, message} in log order), as lib/expert/log_replay.cpp does:
% every input heard delivered, every firing whose DONE the history holds
% fired again with its outputs dropped (the run has them), the last one's
% DONE kept to answer a repeated FIRE. The firing in flight is left to the
% arbiter, which sends it again.
  dones = history(strcmp(history(:, 1), 'DONE'), 2);
  dones = dones(cellfun(@(done) strcmp(done.expert, core.name), dones));
  done_ids = cellfun(@(done) done.firing_id, dones);
  feeder = struct('pending', [], 'last_fired', [], 'last_id', -1, 'firings', 0, 'inputs', 0);
  for i = 1:size(history, 1)
    [channel, message] = history{i, :};
    if strcmp(channel, 'FIRE')
      if ~strcmp(message.expert, core.name) || message.firing_id <= feeder.last_id
        continue;
      end
      [feeder, ports, state] = fire_pending(feeder, expert, ports, parameters, state);
      feeder.last_id = message.firing_id;
      if any(done_ids == message.firing_id)  % else in flight: not fired here
        feeder.pending = firing_of(message);
      end
    else
      [ports, stored] = store_message(ports, channel, message);
      feeder.inputs = feeder.inputs + stored;
    end
    if ~isempty(feeder.pending) && inputs_ready(ports, feeder.pending)
      [feeder, ports, state] = fire_pending(feeder, expert, ports, parameters, state);
    end
  end
  [feeder, ports, state] = fire_pending(feeder, expert, ports, parameters, state);
  core = adopt(core, feeder, dones, done_ids);
  say(core.name, 'resumed from the run''s history: %d firings and %d inputs replayed', feeder.firings, ...
      feeder.inputs);
end

function [feeder, ports, state] = fire_pending(feeder, expert, ports, parameters, state)
  if isempty(feeder.pending)
    return;
  end
  [~, ~, state] = run_fire(expert, feeder.pending, ports, parameters, state);
  feeder.firings = feeder.firings + 1;
  feeder.last_fired = feeder.pending;
  feeder.pending = [];
end

function ready = inputs_ready(ports, firing)
  [~, lacking] = inputs_of_tick(ports, firing.tick);
  ready = isempty(lacking);
end

% The last firing replayed counts as done: its logged DONE is sent again if
% the arbiter asks, with the sender and published lists left to the bridge.
function core = adopt(core, feeder, dones, done_ids)
  if isempty(feeder.last_fired)
    return;
  end
  done = dones{find(done_ids == feeder.last_fired.firing_id, 1)};
  core.pending = feeder.last_fired;
  core.pending_fired = true;
  core.last_fired_id = feeder.last_fired.firing_id;
  core.last_done = done_message(core.name, feeder.last_fired, '', done.duration);
  core.last_done.outcome = done.outcome;
  core.last_done.message = done.message;
end
