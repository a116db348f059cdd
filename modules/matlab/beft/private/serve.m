function status = serve(s, core, expert, ports, state, parameters)
% The live loop: frames from the bridge, firings when due, until the run
% ends (0) or the bridge goes away (1). Heartbeats go on from their own
% thread (beft.Heartbeats); the loop tells it what the expert is doing.
  told = struct('state', '', 'last_fired_id', NaN);
  sent = struct('firing_id', -1, 'text', '');  % the last DONE, kept to send again as it was
  while ~core.run_ended
    [s, event] = take_frame(s, 100);
    switch event.kind
      case 'closed'
        say(s.name, '%s; exiting (restarted, this process resumes)', event.reason);
        status = 1;
        return;
      case 'advertised'
        s = subscribe_wanted(s);  % channels advertised late
      case 'data'
        [core, ports, sent] = on_message(s, core, ports, sent, event.topic, event.message);
    end
    due = false;
    if ~isempty(core.pending) && ~core.pending_fired
      [core, due] = core_firing_due(core, ports);
    end
    if due
      [core, state, outputs, done] = core_fire(core, expert, ports, parameters, state);
      [texts, core, done] = output_texts(s, core, outputs, done);
      for i = 1:size(texts, 1)  % before the DONE, on one ordered socket
        send_text(s, texts{i, :});
      end
      sent = struct('firing_id', done.firing_id, 'text', publish(s, 'DONE', done));
    end
    told = tell_heartbeats(s.beats, core, told);
  end
  say(s.name, 'run ended: %s (%d firings)', core.run_end_reason, core.firings_run);
  status = 0;
end

function [core, ports, sent] = on_message(s, core, ports, sent, topic, message)
  switch topic
    case 'FIRE'
      [core, again] = core_on_fire(core, message);
      if isempty(again)
        return;
      elseif again.firing_id == sent.firing_id  % a repeated FIRE: every 5 ms until the DONE is heard
        send_text(s, 'DONE', sent.text);
      else
        sent = struct('firing_id', again.firing_id, 'text', publish(s, 'DONE', again));
      end
    case 'RUN_STATUS'
      if message.state == 2 || message.state == 3  % finished, failed
        core.run_ended = true;
        core.run_end_reason = message.message;
      elseif message.state == 0  % an arbiter waiting for heartbeats
        s.beats.beatNow();
      end
    otherwise
      ports = store_message(ports, topic, message);
  end
end

% The outputs as JSON; one that cannot be written (a value JSON or its
% type has no place for) fails the firing, and nothing is published.
function [texts, core, done] = output_texts(s, core, outputs, done)
  texts = cell(size(outputs));
  try
    for i = 1:size(outputs, 1)
      texts(i, :) = {outputs{i, 1}, message_text(s, outputs{i, 1}, outputs{i, 2})};
    end
  catch err
    texts = cell(0, 2);
    done.outcome = 1;
    done.message = sprintf('%s not written: %s', outputs{i, 1}, err.message);
    core.last_done = done;
    say(s.name, 'firing %d (tick %d) failed: %s', done.firing_id, done.tick, done.message);
  end
end

% The heartbeat's state (idle, firing, or waiting for the firing's inputs)
% and last firing, told to the heartbeat thread when they change.
function told = tell_heartbeats(beats, core, told)
  if ~core.firing
    state = 'idle';
  elseif core.waiting
    state = 'waiting';
  else
    state = 'firing';
  end
  if ~strcmp(state, told.state) || core.last_fired_id ~= told.last_fired_id
    beats.update(core.last_fired_id, state);
    told = struct('state', state, 'last_fired_id', core.last_fired_id);
  end
end
