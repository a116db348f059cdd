function expert = beft_expert(name, description)
%BEFT_EXPERT  A new expert: its name (the process the arbiter fires) and what it does.
%   expert = beft_expert('geometry', 'distance and azimuth of every scene object');
%   Then declare its inputs (beft_tick_input, beft_scene_input,
%   beft_latest_input), outputs (beft_output) and parameters
%   (beft_parameter), set expert.fire, and run it with beft_run_expert.
%
%   expert.fire is called once per firing whose inputs are ready:
%     [outputs, failure, state] = fire(firing, inputs, parameters, state)
%   firing      utime, tick, firing_id, transition, expert of the FIRE token
%   inputs      one field per channel read: the message of the firing's tick
%               (GT_OBJECTS: the ground truth of the tick), or [] if none;
%               inputs.latest: the newest message of each, whatever its tick
%   parameters  one field per parameter, its value
%   state       what the last firing returned (expert.state at first)
%   outputs     one field per channel written: a message (a struct), or a
%               cell array of messages; struct() for none
%   failure     '' on success, else why the firing failed
  expert = struct('name', name, 'description', description, ...
                  'inputs', struct('channel', {}, 'type', {}, 'kind', {}, 'capacity', {}, 'optional', {}), ...
                  'outputs', struct('channel', {}, 'type', {}), ...
                  'parameters', struct('name', {}, 'kind', {}, 'default', {}, 'value', {}, 'low', {}, ...
                                       'high', {}, 'low_open', {}, 'high_open', {}, 'range', {}, 'meaning', {}), ...
                  'fire', [], 'state', []);
end
