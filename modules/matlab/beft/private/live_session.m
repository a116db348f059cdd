function status = live_session(expert, options)
% The expert live through the bridge (modules/python/README.md, "The
% protocol"): announces itself, subscribes to FIRE, RUN_STATUS and its
% inputs, and publishes its outputs, DONE and HEARTBEAT as JSON, which the
% bridge checks and publishes on the run's channels. 0 at the end of the
% run; 1 when the bridge cannot be reached or goes away (crash-only: its
% supervisor restarts it with --resume-log); 2 when the bridge refuses it.
  load_java();
  name = options.name;
  socket = connect_bridge(name, options.url, options.connect_timeout);
  if isempty(socket)
    status = 1;
    return;
  end
  closer = onCleanup(@() socket.close()); %#ok<NASGU>
  say(name, 'connected to %s', options.url);
  s = new_session(expert, name, socket);
  socket.sendText(client_advertise(s.client_topics, s.client_types));
  publish(s, '/beft/expert', announcement(expert, name, options.resume_log));
  % Beating from now on (the bridge takes them once it has the announcement):
  % replaying a long history takes Octave seconds, the arbiter's patience
  % with a silent expert is 3 s.
  s.beats = javaObject('beft.Heartbeats', socket, find(strcmp(s.client_topics, 'HEARTBEAT')), name, ...
                       options.heartbeat_period, 'starting');
  stopper = onCleanup(@() s.beats.stop()); %#ok<NASGU>
  while isempty(s.accepted)
    [s, event] = take_frame(s, 1000);
    if strcmp(event.kind, 'closed')
      say(name, '%s; exiting', event.reason);
      status = 1;
      return;
    end
  end
  if ~s.accepted
    status = 2;
    return;
  end
  core = new_core(name, options.ready_timeout);
  ports = input_stores(expert.inputs);
  parameters = parameter_values(expert.parameters);
  state = expert.state;
  if ~isempty(options.resume_log)
    [core, ports, state] = resume_from_history(core, expert, history_events(socket), ports, parameters, state);
  end
  s = subscribe_wanted(s);
  status = serve(s, core, expert, ports, state, parameters);
end

function s = new_session(expert, name, socket)
  s = struct('socket', socket, 'beats', [], 'name', name, 'accepted', [], ...
             'client_topics', {[{'/beft/expert'}, {expert.outputs.channel}, {'DONE', 'HEARTBEAT'}]}, ...
             'client_types', {[{'beft.external_expert'}, {expert.outputs.type}, ...
                                {'beft.done_t', 'beft.heartbeat_t'}]}, ...
             'server_topics', {{}}, 'server_ids', [], 'schemas', struct(), ...
             'wanted', {[{'FIRE', 'RUN_STATUS'}, {expert.inputs.channel}]}, 'subscribed', {{}}, ...
             'last_fire', struct('text', '', 'hex', '', 'message', []));
end
