function text = publish(s, topic, message)
% Publishes a message on one of the client's channels; the text sent is
% returned (to send again as it was: send_text).
  text = message_text(s, topic, message);
  send_text(s, topic, text);
end
